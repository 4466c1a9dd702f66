#include "tracer/renderer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>

#include "image/colour_transfer.hpp"
#include "runtime/objects/object_factory.hpp"
#include "runtime/work_counts.hpp"
#include "tracer/camera_ray.hpp"
#include "tracer/focal_blur.hpp"
#include "tracer/frame_sampling.hpp"
#include "tracer/photon_shooting.hpp"
#include "tracer/radiosity_pretrace.hpp"
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

}  // namespace

Renderer::Renderer(const runtime::SceneDescription& scene, const RenderSettings& settings)
    : Renderer(scene, settings, nullptr) {}

Renderer::Renderer(runtime::SceneDescription& scene, const RenderSettings& settings, ReleaseRecords)
    : Renderer(scene, settings, &scene.objects) {}

Renderer::Renderer(const runtime::SceneDescription& scene, const RenderSettings& settings,
                   Records* release)
    : thread_limit_(settings.threads > 0
                        ? std::make_unique<tbb::global_control>(
                              tbb::global_control::max_allowed_parallelism, settings.threads)
                        : nullptr),
      scene_(scene),
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
    shader_->set_radiosity_path(settings_.gi_path);
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
    // (The estimate costs nothing: whenever its blocks exist.)
    const bool estimate = spp >= 2 && settings_.jitter;
    const bool adaptive = settings_.target_error > 0.0;
    if (adaptive && !estimate)
        throw std::invalid_argument(
            "a target error needs 2 or more jittered samples per pixel (its estimate)");
    Image image(width, height);
    // (Per pixel, the estimated squared error over its channels.)
    std::vector<double> squared(estimate ? static_cast<std::size_t>(width) * height : 0);
    // (Per pixel, the photon map's squared error summed over its samples.)
    std::vector<double> photon_squared(
        estimate && shader_->photons_enabled() ? static_cast<std::size_t>(width) * height : 0);
    std::vector<int> samples(static_cast<std::size_t>(width) * height, 0);
    const bool moving_camera = scene_.camera.depends_on_time();
    const double working_gamma = scene_.global.assumed_gamma;
    const runtime::CameraFrame fixed_camera = scene_.camera.evaluate(open);
    const std::size_t object_count = query_->object_count();
    tbb::enumerable_thread_specific<ThreadState> states([&] {
        return ThreadState{Mailbox(object_count), {}};
    });
    const auto start = std::chrono::steady_clock::now();

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
    // trace_at's sample through `camera`, at the sample's instant t.
    const auto trace_through = [&](const runtime::CameraFrame& camera, double t, double px,
                                   double py, std::uint32_t seed, int index, int count, bool jitter,
                                   ThreadState& state) {
        // POV-Ray's screen: x from -0.5 (left) to 0.5, y from 0.5 (top) to
        // -0.5; left-handed. Focal blur's lens point is one more pair of the
        // sample's dimensions (its own scramble, as an area light's).
        if (camera.mesh) {
            // A mesh camera's sample: its rays averaged over those made
            // (TracePixel::operator()), at POV-Ray's pixel coordinates
            // (CreateCameraRay's, after its half-pixel moves: the row one
            // less than the sample's).
            state.sample = {seed, static_cast<std::uint32_t>(index),
                            static_cast<std::uint32_t>(count), jitter};
            glm::dvec3 sum(0.0);
            unsigned made = 0;
            for (unsigned n = 0; n < camera.mesh->rays_per_pixel(); ++n) {
                const auto ray =
                    camera.mesh->ray(px, py - 1.0, width, height, n, camera.location.z,
                                     camera.direction.z < -1e-10, t);  // (POV-Ray's EPSILON)
                if (!ray) continue;
                glm::dvec3 direction = ray->direction;
                if (camera_normal_) direction = camera_normal_->perturb(direction, {0, 0, 0}, t);
                sum += shader_->trace(travel_.ray(ray->origin, t, direction), state);
                ++made;
            }
            return made ? sum / double(made) : glm::dvec3(0.0);
        }
        const double u = px / width - 0.5;
        const double v = 0.5 - py / height;
        const auto lens = [&] {
            const auto pair = sample_pair(seed, static_cast<std::uint32_t>(index),
                                          static_cast<std::uint32_t>(count), kLensPair, jitter);
            return glm::dvec2(pair[0], pair[1]);
        };
        PrimaryRay ray;
        // (No ray, a fisheye's corner: black, as POV-Ray's.)
        if (!primary_ray(camera, u, v, lens, camera_normal_ ? &*camera_normal_ : nullptr, t, ray))
            return glm::dvec3(0.0);
        state.sample = {seed, static_cast<std::uint32_t>(index), static_cast<std::uint32_t>(count),
                        jitter};
        return shader_->trace(travel_.ray(ray.origin, t, ray.direction), state);
    };
    // The colour seen at (px, py) of the image (pixels' corners at whole
    // numbers) at `time` in [0, 1) across the shutter, as sample `index`
    // of the set with this seed, of `count` in the set, for its further
    // dimensions. (A camera of its own only for a moving one: a frame set
    // aside for each sample cost its 192 bytes' zeroing even unused.)
    const auto trace_at = [&](double px, double py, double time, std::uint32_t seed, int index,
                              int count, bool jitter, ThreadState& state) {
        const double t = frame_clock.at(py / height, time);
        if (moving_camera)
            return trace_through(scene_.camera.evaluate(t), t, px, py, seed, index, count, jitter,
                                 state);
        return trace_through(fixed_camera, t, px, py, seed, index, count, jitter, state);
    };
    // Sample `index` of the set with this seed, of `count` in the set.
    const auto trace_sample = [&](int x, int y, std::uint32_t seed, int index, int count,
                                  ThreadState& state) {
        const PixelSample s = pixel_sample(seed, static_cast<std::uint32_t>(index),
                                           static_cast<std::uint32_t>(count), settings_.jitter);
        return trace_at(x + s.x, y + s.y, s.time, seed, index, count, settings_.jitter, state);
    };

    // Photons: the frame's map, shot across its shutter before anything
    // is traced (radiosity's pretrace sees them too, as in POV-Ray).
    std::optional<PhotonMaps> photons;
    if (shader_->photons_enabled()) {
        photons.emplace(shoot_photons(
            *shader_, objects_, [&](double u) { return frame_clock.at(0.5, u); },
            [&]() -> ThreadState& { return states.local(); }, counters_));
        shader_->set_photon_map(&photons->surface);
        shader_->set_media_photon_map(&photons->media);
    }

    // Radiosity: the frame's irradiance cache, filled by the pretrace
    // (POV-Ray's, per frame) and read by the render.
    std::optional<RadiosityCache> radiosity;
    if (shader_->radiosity_enabled() && settings_.gi_path) {
        shader_->set_radiosity_cache(nullptr, fixed_camera.location);
    } else if (shader_->radiosity_enabled()) {
        radiosity.emplace(shader_->radiosity_reach());
        shader_->set_radiosity_cache(&*radiosity, fixed_camera.location);
        radiosity_pretrace(
            shader_->radiosity_settings(), width, height, *radiosity,
            // (The frame's middle; a seed of the pixel alone, as the
            // pretrace's jitter: a still scene's frames gather alike.)
            [&](double px, double py, ThreadState& state) {
                trace_at(px, py, 0.5, pixel_seed(0, int(px), int(py), settings_.sample_seed), 0, 1,
                         false, state);
            },
            [&]() -> ThreadState& { return states.local(); });
    }

    FramePlan plan;
    plan.frame = frame;
    plan.sample_seed = settings_.sample_seed;
    plan.width = width;
    plan.height = height;
    plan.estimate = estimate;
    plan.adaptive = adaptive;
    plan.ceiling = spp;
    plan.first_round = RenderSettings::kFirstRoundSamples;
    plan.target_error = settings_.target_error;
    // (Deformation maps are counted per thread by the runtime: each
    // sample's go to its thread's counters.)
    const auto counted_sample = [&](int x, int y, std::uint32_t seed, int index, int count,
                                    ThreadState& state) {
        const std::uint64_t maps = runtime::this_thread_work.deformation_maps;
        // (The cache's records a pixel gathers in the final trace serve its
        // later samples of the same run.)
        RadiosityPath& path = state.radiosity;
        if (radiosity) {
            if (path.pixel_run != state.pixel_run) {
                path.pixel.clear();
                path.pixel_run = state.pixel_run;
            }
            path.kept = &path.pixel;
        }
        state.photon_variance = 0.0;
        const glm::dvec3 colour = trace_sample(x, y, seed, index, count, state);
        path.kept = nullptr;
        if (!photon_squared.empty())
            photon_squared[static_cast<std::size_t>(y) * width + x] += state.photon_variance;
        state.counters.deformation_maps += runtime::this_thread_work.deformation_maps - maps;
        return colour;
    };
    const FrameSamplingResult sampled = sample_frame(
        plan, counted_sample, linear, [&]() -> ThreadState& { return states.local(); },
        [&](int x, int y, const PixelBlocks& b, double pixel_squared) {
            const std::size_t at = static_cast<std::size_t>(y) * width + x;
            image.set(x, y, linear(b.mean()));
            samples[at] = b.count;
            if (estimate) squared[at] = pixel_squared;
        },
        [&](double fraction, std::uint64_t total) {
            if (settings_.progress) settings_.progress(frame, fraction, total);
        });
    for (const ThreadState& s : states) counters_ += s.counters;
    shader_->set_radiosity_cache(nullptr, {});
    shader_->set_photon_map(nullptr);
    shader_->set_media_photon_map(nullptr);
    counters_.render_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (estimate) {
        last_estimate_ = estimate_frame(squared, width, height);
        if (!photon_squared.empty()) {
            double sum = 0.0;
            for (std::size_t i = 0; i < photon_squared.size(); ++i)
                sum += samples[i] > 0 ? photon_squared[i] / samples[i] : 0.0;
            last_estimate_->photon_rmse = std::sqrt(sum / double(photon_squared.size()));
        }
        last_squared_ = std::move(squared);
    } else {
        last_estimate_.reset();
        last_squared_.clear();
    }
    last_samples_ = std::move(samples);
    last_sample_count_ = sampled.samples;
    last_tiles_over_target_ = sampled.tiles_over_target;
    last_tile_count_ = sampled.tiles;
    return image;
}

}  // namespace hexant::tracer
