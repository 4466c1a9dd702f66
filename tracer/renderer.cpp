#include "tracer/renderer.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include "image/colour_transfer.hpp"
#include "runtime/objects/object_factory.hpp"
#include "runtime/work_counts.hpp"
#include "tracer/camera_ray.hpp"
#include "tracer/focal_blur.hpp"
#include "tracer/sample_pattern.hpp"

namespace hexant::tracer {

namespace {

using runtime::Box4;
using runtime::Event;

// Calls add(p, t) with every point the eye's rays start from (the lens, an
// orthographic film) and every light's position, at the opening and closing
// of each of frames first..last.
template <class Add>
void for_each_eye_and_light(const runtime::SceneDescription& scene, int first, int last,
                            Add&& add) {
    const auto& a = scene.animation;
    for (int f = first; f <= last; ++f) {
        const runtime::Animation::Window window = a.frame_window(f);
        for (const double t : {window.open, window.close()}) {
            eye_extent(scene.camera.evaluate(t), t, [&](const glm::dvec3& p) { add(p); });
            for (const auto& light : scene.lights) add(light.world_position(t));
        }
    }
}

// How far back in time light of the animation can reach at speed
// `light_speed` (scene units per clock unit; infinite: 0). Every ray starts
// inside the extent of everything the animation holds (its objects, eyes
// and lights) and hits only inside it, so a ray travels at most its
// diagonal; a path is at most max_trace_level rays and one shadow ray.
double light_lookback(const runtime::SceneDescription& scene, const ObjectSet& objects,
                      double light_speed) {
    if (!std::isfinite(light_speed)) return 0.0;
    const auto& a = scene.animation;
    const double begin = std::min(a.time_begin(), a.time_end()),
                 end = std::max(a.time_begin(), a.time_end());
    Box4 all = enclosing_box(objects, begin, end);
    for_each_eye_and_light(scene, a.initial_frame, a.final_frame,
                           [&](const glm::dvec3& p) { all.extend(Event(p, begin)); });
    const double diagonal = glm::length(glm::dvec3(all.hi) - glm::dvec3(all.lo));
    return (std::max(1, scene.global.max_trace_level) + 1) * diagonal / light_speed;
}

// The root cell: the objects' extent over frames first..last (their
// shutters' span, and before it as far back as their light reaches, not
// before the animation), the eye and the lights at each of those frames'
// opening and closing. `floor` gets the root's first instant.
Box4 animation_root(const runtime::SceneDescription& scene, const ObjectSet& objects, int first,
                    int last, double lookback, double& floor) {
    const auto& a = scene.animation;
    // (A clock that runs backwards, --clock 2:1, spans the same time the
    // other way: the root's time is its smaller end to its larger.)
    const double from = a.frame_window(first).open;
    const double to = a.frame_window(last).close();
    const double begin = std::min(from, to), end = std::max(from, to);
    floor =
        lookback > 0.0 ? std::max(std::min(a.time_begin(), a.time_end()), begin - lookback) : begin;
    Box4 root = enclosing_box(objects, floor, end);
    const auto add = [&](const glm::dvec3& p) {
        root.extend(Event(p, floor));
        root.extend(Event(p, end));
    };
    // (Focal blur moves the eye over a lens of radius aperture / 4; an
    // orthographic camera's rays start across its film.)
    for_each_eye_and_light(scene, first, last, add);
    // A flat extent (everything in one plane, or a still) gets a little
    // thickness so that the cells have volume.
    for (int i = 0; i < 4; ++i) {
        if (root.hi[i] > root.lo[i]) continue;
        const double pad = std::max(1e-9, std::fabs(root.lo[i]) * 1e-9);
        root.lo[i] -= pad;
        root.hi[i] += pad;
    }
    return root;
}

// Of `mattering` (the objects that matter to a camera ray inside them:
// Shader::matters_to_camera), those a camera ray of `frame` may start
// inside: whose extent over the frame's shutter meets the box of the eye's
// points at its opening and closing (the root cell assumes as much of the
// eye's path), so that each camera ray tests only those.
std::vector<const runtime::IntelligentObject*> camera_interiors(
    const runtime::SceneDescription& scene,
    const std::vector<const runtime::IntelligentObject*>& mattering, int frame) {
    std::vector<const runtime::IntelligentObject*> out;
    if (mattering.empty()) return out;
    const auto& a = scene.animation;
    const runtime::Animation::Window window = a.frame_window(frame);
    const double open = window.open, close = window.close();
    Box4 eye = Box4::empty();
    for (const double t : {open, close})
        eye_extent(scene.camera.evaluate(t), t,
                   [&](const glm::dvec3& p) { eye.extend(Event(p, t)); });
    for (const runtime::IntelligentObject* o : mattering) {
        if (o->bounded()) {
            const Box4 box =
                o->box_over(runtime::Interval(std::min(open, close), std::max(open, close)));
            bool meets = !box.is_empty() && !eye.is_empty();
            for (int i = 0; meets && i < 3; ++i)
                meets = box.lo[i] <= eye.hi[i] && eye.lo[i] <= box.hi[i];
            if (!meets) continue;
        }
        out.push_back(o);
    }
    return out;
}

// One tile of the frame's fixed grid (FrameEstimate::kTile): its place, and
// how it samples.
struct TilePlan {
    int frame;
    std::uint32_t sample_seed;
    bool halves, adaptive;  // two sample sets; rounds to a target error
    int per_set;            // the samples of each set at most
    double target_error;
    int x0, y0, width, pixels;
};

// A tile's samples: per pixel the sums of its first and (halves) its
// second, independent set, and its estimated squared error after the last
// round; how many samples each set took, and whether the ceiling was
// reached above the target.
struct TileSamples {
    std::array<glm::dvec3, FrameEstimate::kTile * FrameEstimate::kTile> sum_a, sum_b;
    std::array<double, FrameEstimate::kTile * FrameEstimate::kTile> pixel_squared{};
    int taken = 0;
    bool over_target = false;
};

// Samples a tile in rounds: samples [taken, goal) of each set, then the
// tile's estimate decides whether to double (adaptive only). What a tile
// does depends on its own samples only. `trace(x, y, seed, index, count,
// state)` gives one sample; `linear` takes a colour to linear light.
template <class Trace, class Linear>
TileSamples sample_tile(const TilePlan& plan, Trace&& trace, Linear&& linear, ThreadState& state) {
    TileSamples out;
    out.sum_a.fill(glm::dvec3(0.0));
    out.sum_b.fill(glm::dvec3(0.0));
    const int per_set = plan.per_set, pixels = plan.pixels;
    int& taken = out.taken;
    int goal = plan.adaptive ? std::min(per_set, RenderSettings::kFirstRoundSamples / 2) : per_set;
    double tile_squared = 0.0;
    while (true) {
        for (int p = 0; p < pixels; ++p) {
            const int x = plan.x0 + p % plan.width, y = plan.y0 + p / plan.width;
            const std::uint32_t seed = pixel_seed(plan.frame, x, y, plan.sample_seed);
            const std::uint32_t second = plan.halves ? second_set_seed(seed) : 0;
            for (int i = taken; i < goal; ++i) {
                out.sum_a[p] += trace(x, y, seed, i, per_set, state);
                if (plan.halves) out.sum_b[p] += trace(x, y, second, i, per_set, state);
            }
        }
        taken = goal;
        if (plan.halves) {
            tile_squared = 0.0;
            for (int p = 0; p < pixels; ++p) {
                // (A - B)^2 / 4 per channel, each half in linear light.
                const glm::dvec3 d =
                    linear(out.sum_a[p] / double(taken)) - linear(out.sum_b[p] / double(taken));
                out.pixel_squared[p] = glm::dot(d, d) / 12.0;
                tile_squared += out.pixel_squared[p];
            }
        }
        if (!plan.adaptive || std::sqrt(tile_squared / pixels) <= plan.target_error) break;
        if (taken == per_set) {
            out.over_target = true;  // (the ceiling reached above the target)
            break;
        }
        goal = std::min(per_set, 2 * taken);
    }
    return out;
}

}  // namespace

Renderer::Renderer(const runtime::SceneDescription& scene, const RenderSettings& settings)
    : Renderer(scene, settings, nullptr) {}

Renderer::Renderer(runtime::SceneDescription& scene, const RenderSettings& settings, ReleaseRecords)
    : Renderer(scene, settings, &scene.objects) {}

Renderer::Renderer(const runtime::SceneDescription& scene, const RenderSettings& settings,
                   Records* release)
    : scene_(scene),
      settings_(settings),
      first_frame_(settings.first_frame > 0 ? settings.first_frame : scene.animation.initial_frame),
      last_frame_(settings.last_frame > 0 ? settings.last_frame : scene.animation.final_frame) {
    if (first_frame_ < scene.animation.initial_frame || last_frame_ > scene.animation.final_frame ||
        first_frame_ > last_frame_)
        throw std::out_of_range("frames " + std::to_string(first_frame_) + " to " +
                                std::to_string(last_frame_) + " are not all in the animation");
    // (A ray that travels in time cannot be moved into an instance's space
    // by one placement.)
    const runtime::ObjectOptions object_options{settings.build.instances &&
                                                std::isinf(settings.light_speed)};
    if (release) {
        // Each record goes as soon as its objects are made: the heap it
        // leaves is what the next objects reuse.
        for (auto& record : *release) {
            runtime::make_intelligent_objects(*record, scene.default_texture, objects_,
                                              object_options);
            record.reset();
        }
        release->clear();
        release->shrink_to_fit();
    } else {
        for (const auto& record : scene.objects)
            runtime::make_intelligent_objects(*record, scene.default_texture, objects_,
                                              object_options);
    }
    counters_.objects = objects_.size();
    const ObjectSet set = ObjectSet::of(objects_);
    const std::uint64_t maps = runtime::this_thread_work.deformation_maps;
    if (!(settings.light_speed > 0.0))
        throw std::invalid_argument(
            "the speed of light must be a positive number (infinite: instant light)");
    lookback_ = light_lookback(scene, set, settings.light_speed);
    root_ = animation_root(scene, set, first_frame_, last_frame_, lookback_, floor_);
    counters_.deformation_maps += runtime::this_thread_work.deformation_maps - maps;
    // What the cost criterion weighs a split against: the rays of a frame
    // (primary, and a shadow ray per light that casts shadows; reflections
    // and refractions are not foreseen).
    BuildOptions build = settings.build;
    if (build.rays_per_frame == 0.0) {
        double lights = 0.0;
        for (const auto& light : scene.lights) lights += light.shadowless ? 0.0 : 1.0;
        // (Adaptive sampling takes an unknown count under its ceiling: the
        // mean at the default target is 8 to 26 samples on the examples
        // (docs/benchmarks.md, "Error against run time"), so twice the first round.)
        const int samples =
            settings.target_error > 0.0
                ? std::min(settings.samples_per_pixel, 2 * RenderSettings::kFirstRoundSamples)
                : settings.samples_per_pixel;
        build.rays_per_frame = double(scene.animation.width) * scene.animation.height *
                               std::max(1, samples) * (1.0 + lights);
        build.frame_interval = std::fabs(scene.animation.clock_delta());
        build.shutter_time = std::fabs(scene.animation.exposure() * scene.animation.clock_delta());
    }
    query_ = make_ray_query(settings.mode, set, root_, build, counters_);
    LightTravel travel;
    if (std::isfinite(settings.light_speed)) {
        travel.time_per_distance = 1.0 / settings.light_speed;
        travel.floor = floor_;
    }
    travel_ = travel;
    const bool filtering = std::any_of(objects_.begin(), objects_.end(), [](const auto& o) {
        return o->casts_shadow() && o->filters_light();
    });
    shader_ = std::make_unique<Shader>(scene, *query_, travel, filtering);
    const bool refracting = std::any_of(objects_.begin(), objects_.end(),
                                        [](const auto& o) { return o->filters_light(); });
    for (const auto& o : objects_)
        if (Shader::matters_to_camera(scene, *o, refracting)) camera_mattering_.push_back(o.get());
    if (scene.camera.normal) {
        runtime::Texture screen;
        screen.normal = *scene.camera.normal;
        camera_normal_.emplace(screen, std::nullopt);
    }
}

Renderer::~Renderer() = default;

Image Renderer::render_frame(int frame) {
    if (frame < first_frame_ || frame > last_frame_)
        throw std::out_of_range("frame " + std::to_string(frame) + " is not among the frames " +
                                std::to_string(first_frame_) + " to " +
                                std::to_string(last_frame_) + " this renderer was built for");
    const auto& a = scene_.animation;
    const runtime::Animation::Window window = a.frame_window(frame);
    const double open = window.open;
    const double length = window.length;
    const runtime::Animation::FrameClock frame_clock = a.frame_clock(frame);
    // (Light of finite speed reaches back before the shutter opens.)
    const double first_instant = std::min(open, open + length);
    // What preparing takes beyond the builds it counts itself (the frame
    // baseline's hierarchy) is the frame's: spacetime mode builds the cells
    // of its time index here, which rays built inside the render before.
    const double build_before = counters_.build_seconds;
    const auto prepare_start = std::chrono::steady_clock::now();
    query_->prepare_frame(
        lookback_ > 0.0 ? std::max(floor_, first_instant - lookback_) : first_instant,
        std::max(open, open + length), counters_);
    counters_.render_seconds += std::max(
        0.0,
        std::chrono::duration<double>(std::chrono::steady_clock::now() - prepare_start).count() -
            (counters_.build_seconds - build_before));
    shader_->set_camera_interiors(camera_interiors(scene_, camera_mattering_, frame));

    const int width = a.width, height = a.height;
    const int spp = std::max(1, settings_.samples_per_pixel);
    const bool halves = settings_.sample_sets == 2;
    const bool adaptive = settings_.target_error > 0.0;
    if (halves && (spp % 2 != 0 || !settings_.jitter))
        throw std::invalid_argument(
            "two sample sets need an even number of jittered samples per pixel");
    if (adaptive && !halves)
        throw std::invalid_argument("a target error needs two sample sets (its estimate)");
    Image image(width, height);
    // (Per pixel, the estimated squared error over its channels: halves only.)
    std::vector<double> squared(halves ? static_cast<std::size_t>(width) * height : 0);
    std::vector<int> samples(static_cast<std::size_t>(width) * height, 0);
    const bool moving_camera = scene_.camera.depends_on_time();
    const double working_gamma = scene_.global.assumed_gamma;
    const runtime::CameraFrame fixed_camera = scene_.camera.evaluate(open);
    const std::size_t object_count = query_->object_count();
    tbb::enumerable_thread_specific<ThreadState> states([&] {
        return ThreadState{Mailbox(object_count), {}};
    });
    const auto start = std::chrono::steady_clock::now();

    std::unique_ptr<tbb::global_control> limit;
    if (settings_.threads > 0)
        limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                      settings_.threads);
    // assumed_gamma G: the scene's colours and all the shading are in a
    // space of gamma G; the pixel leaves it (POV-Ray 3.7 decodes the working
    // gamma before it encodes the file's).
    // Without gamma correction (a legacy scene), the value computed is the
    // one the file holds: decoded here so that the sRGB encoding of 8-bit
    // output gives it back (an OpenEXR frame then holds it decoded).
    const bool raw = !scene_.global.gamma_correction;
    const auto linear = [&](glm::dvec3 c) {
        if (raw) {
            for (int k = 0; k < 3; ++k) c[k] = image::srgb_decode(std::max(c[k], 0.0));
            return c;
        }
        if (working_gamma != 1.0)
            for (int k = 0; k < 3; ++k) c[k] = std::pow(std::max(c[k], 0.0), working_gamma);
        return c;
    };
    // Sample `index` of the set with this seed, of `count` in the set.
    const auto trace_sample = [&](int x, int y, std::uint32_t seed, int index, int count,
                                  ThreadState& state) {
        const PixelSample s = pixel_sample(seed, static_cast<std::uint32_t>(index),
                                           static_cast<std::uint32_t>(count), settings_.jitter);
        const double t = frame_clock.at((y + s.y) / height, s.time);
        std::optional<runtime::CameraFrame> moved;
        if (moving_camera) moved.emplace(scene_.camera.evaluate(t));
        const runtime::CameraFrame& camera = moving_camera ? *moved : fixed_camera;
        // POV-Ray's screen: x from -0.5 (left) to 0.5, y from 0.5 (top) to
        // -0.5; left-handed. Focal blur's lens point is one more pair of the
        // sample's dimensions (its own scramble, as an area light's).
        if (camera.mesh) {
            // A mesh camera's sample: its rays averaged over those made
            // (TracePixel::operator()), at POV-Ray's pixel coordinates
            // (CreateCameraRay's, after its half-pixel moves: the row one
            // less than the sample's).
            state.sample = {seed, static_cast<std::uint32_t>(index),
                            static_cast<std::uint32_t>(count), settings_.jitter};
            glm::dvec3 sum(0.0);
            unsigned made = 0;
            for (unsigned n = 0; n < camera.mesh->rays_per_pixel(); ++n) {
                const auto ray =
                    camera.mesh->ray(x + s.x, y + s.y - 1.0, width, height, n, camera.location.z,
                                     camera.direction.z < -1e-10, t);  // (POV-Ray's EPSILON)
                if (!ray) continue;
                glm::dvec3 direction = ray->direction;
                if (camera_normal_) direction = camera_normal_->perturb(direction, {0, 0, 0}, t);
                sum += shader_->trace(travel_.ray(ray->origin, t, direction), state);
                ++made;
            }
            return made ? sum / double(made) : glm::dvec3(0.0);
        }
        const double u = (x + s.x) / width - 0.5;
        const double v = 0.5 - (y + s.y) / height;
        const auto lens = [&] {
            const auto pair =
                sample_pair(seed, static_cast<std::uint32_t>(index),
                            static_cast<std::uint32_t>(count), kLensPair, settings_.jitter);
            return glm::dvec2(pair[0], pair[1]);
        };
        const std::optional<PrimaryRay> ray =
            primary_ray(camera, u, v, lens, camera_normal_ ? &*camera_normal_ : nullptr, t);
        // (No ray, a fisheye's corner: black, as POV-Ray's.)
        if (!ray) return glm::dvec3(0.0);
        state.sample = {seed, static_cast<std::uint32_t>(index), static_cast<std::uint32_t>(count),
                        settings_.jitter};
        return shader_->trace(travel_.ray(ray->origin, t, ray->direction), state);
    };

    // The fixed grid of tiles (the estimate's, FrameEstimate::kTile): what
    // a tile does depends on its own samples only.
    constexpr int kTile = FrameEstimate::kTile;
    const int tiles_x = (width + kTile - 1) / kTile, tiles_y = (height + kTile - 1) / kTile;
    const int tile_count = tiles_x * tiles_y;
    const int per_set = halves ? spp / 2 : spp;
    std::atomic<int> tiles_done{0}, tiles_over{0};
    std::atomic<std::uint64_t> samples_taken{0};
    std::mutex progress_mutex;
    tbb::parallel_for(
        tbb::blocked_range<int>(0, tile_count, 1), [&](const tbb::blocked_range<int>& range) {
            ThreadState& state = states.local();
            const std::uint64_t maps = runtime::this_thread_work.deformation_maps;
            for (int tile = range.begin(); tile < range.end(); ++tile) {
                const int x0 = tile % tiles_x * kTile, y0 = tile / tiles_x * kTile;
                const int x1 = std::min(width, x0 + kTile), y1 = std::min(height, y0 + kTile);
                const int tile_width = x1 - x0, pixels = tile_width * (y1 - y0);
                TilePlan plan{frame,      settings_.sample_seed,
                              halves,     adaptive,
                              per_set,    settings_.target_error,
                              x0,         y0,
                              tile_width, pixels};
                const TileSamples t = sample_tile(plan, trace_sample, linear, state);
                if (t.over_target) ++tiles_over;
                const auto& sum_a = t.sum_a;
                const auto& sum_b = t.sum_b;
                const auto& pixel_squared = t.pixel_squared;
                const int taken = t.taken;
                const int sets = halves ? 2 : 1;
                for (int p = 0; p < pixels; ++p) {
                    const int x = x0 + p % tile_width, y = y0 + p / tile_width;
                    const std::size_t at = static_cast<std::size_t>(y) * width + x;
                    image.set(x, y, linear((sum_a[p] + sum_b[p]) / double(sets * taken)));
                    samples[at] = sets * taken;
                    if (halves) squared[at] = pixel_squared[p];
                }
                const std::uint64_t total = samples_taken += std::uint64_t(pixels) * sets * taken;
                const int done = ++tiles_done;
                if (settings_.progress) {
                    const std::lock_guard<std::mutex> lock(progress_mutex);
                    settings_.progress(frame, double(done) / tile_count, total);
                }
            }
            state.counters.deformation_maps += runtime::this_thread_work.deformation_maps - maps;
        });
    for (const ThreadState& s : states) counters_ += s.counters;
    counters_.render_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (halves) {
        last_estimate_ = estimate_frame(squared, width, height);
        last_squared_ = std::move(squared);
    } else {
        last_estimate_.reset();
        last_squared_.clear();
    }
    last_samples_ = std::move(samples);
    last_sample_count_ = samples_taken;
    last_tiles_over_target_ = tiles_over;
    last_tile_count_ = tile_count;
    return image;
}

}  // namespace hexant::tracer
