#include "app/mode_run.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

#include <sys/resource.h>
#include <unistd.h>

#include "app/out_of_memory.hpp"
#include "tracer/image_output.hpp"
#include "tracer/renderer.hpp"
#include "tracer/whole_file.hpp"

namespace hexant::app {

namespace {

using tracer::Counters;

struct Row {
    const char* name;
    double (*value)(const Counters&);
    int decimals;
};

double per_ray(std::uint64_t n, const Counters& c) {
    return c.rays() ? double(n) / double(c.rays()) : 0.0;
}

const Row kRows[] = {
    {"primary rays", [](const Counters& c) { return double(c.primary_rays); }, 0},
    {"shadow rays", [](const Counters& c) { return double(c.shadow_rays); }, 0},
    {"reflected rays", [](const Counters& c) { return double(c.reflected_rays); }, 0},
    {"refracted rays", [](const Counters& c) { return double(c.refracted_rays); }, 0},
    {"radiosity rays", [](const Counters& c) { return double(c.radiosity_rays); }, 0},
    {"radiosity samples", [](const Counters& c) { return double(c.radiosity_samples); }, 0},
    {"radiosity reuses", [](const Counters& c) { return double(c.radiosity_reuses); }, 0},
    {"photon rays", [](const Counters& c) { return double(c.photon_rays); }, 0},
    {"photons stored", [](const Counters& c) { return double(c.photons_stored); }, 0},
    {"media photons stored", [](const Counters& c) { return double(c.media_photons_stored); }, 0},
    {"photon gathers", [](const Counters& c) { return double(c.photon_gathers); }, 0},
    {"dispersed rays", [](const Counters& c) { return double(c.dispersed_rays); }, 0},
    {"objects", [](const Counters& c) { return double(c.objects); }, 0},
    {"bounds built", [](const Counters& c) { return double(c.bounds_built); }, 0},
    {"hierarchy cells", [](const Counters& c) { return double(c.cells); }, 0},
    // (Not counted without --stats-full: none.)
    {"cells of a full build",
     [](const Counters& c) {
         return c.cells_full > 0 || c.cells == 0 ? double(c.cells_full)
                                                 : std::numeric_limits<double>::quiet_NaN();
     },
     0},
    {"box nodes", [](const Counters& c) { return double(c.box_nodes); }, 0},
    {"linear-motion nodes", [](const Counters& c) { return double(c.motion_nodes); }, 0},
    {"piecewise-motion nodes", [](const Counters& c) { return double(c.piece_nodes); }, 0},
    {"12-slab nodes", [](const Counters& c) { return double(c.slab_nodes); }, 0},
    {"time nodes", [](const Counters& c) { return double(c.time_nodes); }, 0},
    {"object references", [](const Counters& c) { return double(c.object_refs); }, 0},
    {"node tests", [](const Counters& c) { return double(c.node_tests); }, 0},
    {"ray/bound tests", [](const Counters& c) { return double(c.bound_tests); }, 0},
    {"ray/object tests", [](const Counters& c) { return double(c.object_tests); }, 0},
    {"node tests per ray", [](const Counters& c) { return per_ray(c.node_tests, c); }, 2},
    {"ray/bound tests per ray", [](const Counters& c) { return per_ray(c.bound_tests, c); }, 2},
    {"ray/object tests per ray", [](const Counters& c) { return per_ray(c.object_tests, c); }, 2},
    {"time splits", [](const Counters& c) { return double(c.time_splits); }, 0},
    {"deformation maps", [](const Counters& c) { return double(c.deformation_maps); }, 0},
    {"filtered shadow surfaces", [](const Counters& c) { return double(c.filtered_surfaces); }, 0},
    {"rays travelling in time", [](const Counters& c) { return double(c.travelling_rays); }, 0},
    {"node memory (MB)", [](const Counters& c) { return double(c.node_bytes) / (1 << 20); }, 1},
    {"sweep memory (MB)", [](const Counters& c) { return double(c.sweep_bytes) / (1 << 20); }, 1},
    {"memory at start (MB)", [](const Counters& c) { return c.memory_start_mb; }, 1},
    {"peak memory (MB)", [](const Counters& c) { return c.memory_peak_mb; }, 1},
    {"build time (s)", [](const Counters& c) { return c.build_seconds; }, 3},
    {"sweep time (s)", [](const Counters& c) { return c.sweep_seconds; }, 3},
    {"lazy build in render (s)", [](const Counters& c) { return c.lazy_build_seconds; }, 3},
    {"render time (s)", [](const Counters& c) { return c.render_seconds; }, 3},
    {"total time (s)", [](const Counters& c) { return c.build_seconds + c.render_seconds; }, 3},
    {"rays per second (M)",
     [](const Counters& c) {
         return c.render_seconds > 0.0 ? double(c.rays()) / c.render_seconds * 1e-6 : 0.0;
     },
     2},
};

// A JSON number, or null for what JSON cannot hold (an infinite estimate
// of a frame whose colours overflow).
std::string json_number(double v) {
    if (!std::isfinite(v)) return "null";
    std::ostringstream out;
    out << std::setprecision(17) << v;
    return out.str();
}

// The process's resident memory now, and its peak so far (Linux).
double resident_mb() {
    long pages = 0, resident = 0;
    if (FILE* f = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2) resident = 0;
        std::fclose(f);
    }
    return double(resident) * double(sysconf(_SC_PAGESIZE)) / (1 << 20);
}

double peak_resident_mb() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return double(usage.ru_maxrss) / 1024.0;  // kilobytes on Linux
}

// The progress line on a terminal: the frame, the frames done of all, the
// samples per second so far and the time left at that pace.
class ProgressLine {
  public:
    // (`done`: frames rendered before this line's first.)
    ProgressLine(std::size_t frames, std::size_t done)
        : frames_(frames), done_(done), start_(Clock::now()) {}
    void update(int frame, double fraction, std::uint64_t frame_samples) {
        const auto now = Clock::now();
        if (now - shown_ < std::chrono::milliseconds(100) && fraction < 1.0) return;
        shown_ = now;
        const double elapsed = std::chrono::duration<double>(now - start_).count();
        const double done = double(done_ - done_before_) + fraction;
        char line[160];
        std::snprintf(
            line, sizeof line, "\rframe %d (%zu of %zu done): %3d%%, %.2f M samples/s, %s left ",
            frame, done_, frames_, int(fraction * 100.0),
            elapsed > 0.0 ? double(samples_ + frame_samples) / elapsed * 1e-6 : 0.0,
            done > 0.0 ? duration(elapsed / done * (double(frames_ - done_) - fraction)).c_str()
                       : "?");
        std::cerr << line << std::flush;
        width_ = std::max(width_, std::strlen(line));
    }
    void frame_done(std::uint64_t frame_samples) {
        ++done_;
        samples_ += frame_samples;
    }
    void clear() {
        if (width_) std::cerr << "\r" << std::string(width_, ' ') << "\r" << std::flush;
    }

  private:
    using Clock = std::chrono::steady_clock;
    static std::string duration(double seconds) {
        char text[32];
        seconds = std::ceil(seconds);  // (never "0 s" with work left)
        if (seconds < 60.0)
            std::snprintf(text, sizeof text, "%.0f s", seconds);
        else if (seconds < 3600.0)
            std::snprintf(text, sizeof text, "%d min %02d s", int(seconds) / 60, int(seconds) % 60);
        else
            std::snprintf(text, sizeof text, "%d h %02d min", int(seconds) / 3600,
                          int(seconds) / 60 % 60);
        return text;
    }
    std::size_t frames_, done_, done_before_ = done_, width_ = 0;
    std::uint64_t samples_ = 0;
    Clock::time_point start_, shown_{};
};

}  // namespace

void print_stats(std::ostream& out, const std::vector<std::pair<std::string, Counters>>& columns) {
    out << std::left << std::setw(26) << "";
    for (const auto& c : columns) out << std::right << std::setw(16) << c.first;
    // The paper's ratio column: the second column over the first
    // (spacetime to frame-by-frame).
    if (columns.size() == 2) out << std::setw(10) << "ratio";
    out << "\n";
    for (const Row& row : kRows) {
        out << std::left << std::setw(26) << row.name;
        for (const auto& c : columns) {
            const double v = row.value(c.second);
            out << std::right << std::setw(16) << std::fixed << std::setprecision(row.decimals);
            if (std::isfinite(v))
                out << v;
            else
                out << "-";
        }
        if (columns.size() == 2) {
            const double a = row.value(columns[0].second), b = row.value(columns[1].second);
            out << std::setw(10) << std::setprecision(2);
            if (a > 0.0 && std::isfinite(b))
                out << b / a;
            else
                out << "-";
        }
        out << "\n";
    }
}

void write_stats_json(const std::string& path,
                      const std::vector<std::pair<std::string, ModeRun>>& columns) {
    std::ostringstream json;
    json << "{\n" << std::setprecision(17);
    for (std::size_t i = 0; i < columns.size(); ++i) {
        json << "  \"" << columns[i].first << "\": {";
        for (std::size_t r = 0; r < std::size(kRows); ++r)
            json << (r ? ", " : "") << "\"" << kRows[r].name
                 << "\": " << json_number(kRows[r].value(columns[i].second.counters));
        // Each frame on a line of its own.
        json << ",\n    \"per frame\": [";
        const auto& frames = columns[i].second.frames;
        for (std::size_t f = 0; f < frames.size(); ++f) {
            const FrameRecord& r = frames[f];
            json << (f ? "," : "") << "\n      {\"frame\": " << r.frame
                 << ", \"seconds\": " << json_number(r.seconds)
                 << ", \"samples per pixel\": " << json_number(r.mean_samples);
            if (r.estimate) {
                json << ", \"tiles over target\": " << r.tiles_over_target
                     << ", \"estimated rmse\": " << json_number(r.estimate->rmse)
                     << ", \"worst tiles\": [";
                for (std::size_t t = 0; t < r.estimate->worst.size(); ++t) {
                    const auto& tile = r.estimate->worst[t];
                    json << (t ? ", " : "") << "{\"x\": " << tile.x << ", \"y\": " << tile.y
                         << ", \"rmse\": " << json_number(tile.rmse) << "}";
                }
                json << "]";
            }
            json << "}";
        }
        json << "]}" << (i + 1 < columns.size() ? "," : "") << "\n";
    }
    json << "}\n";
    tracer::write_text_file(path, json.str());
}

ModeRun render_mode(runtime::SceneDescription& scene, const RenderArguments& args,
                    const Sampling& sampling, tracer::Mode mode, const std::string& pattern,
                    const std::vector<int>& frames, bool write, std::vector<tracer::Image>* keep,
                    bool last_use, std::ostream& err, FramesOf of, const FrameSink& sink) {
    tracer::RenderSettings settings;
    settings.mode = mode;
    settings.samples_per_pixel = sampling.samples;
    settings.target_error = sampling.target_error;
    settings.jitter = !args.no_jitter;
    settings.sample_seed = args.seed;
    settings.threads = args.threads.value_or(0);
    if (args.light_speed) settings.light_speed = *args.light_speed;
    settings.gi_path = args.gi_path;
    settings.build = args.hierarchy.options();
    settings.first_frame = frames.front();
    settings.last_frame = frames.back();
    // Counting a full build builds, after the render, what the lazy build
    // left: as long as the render itself on a large scene (issue 43), so
    // only on demand (and for --compare, the paper's tables).
    settings.build.count_full = args.stats_full || args.compare;
    std::optional<ProgressLine> progress;
    if (isatty(STDERR_FILENO)) {
        progress.emplace(of.total ? of.total : frames.size(), of.done);
        settings.progress = [&](int frame, double fraction, std::uint64_t samples) {
            progress->update(frame, fraction, samples);
        };
    }
    const double start_mb = resident_mb();
    const std::string size =
        std::to_string(scene.animation.width) + " by " + std::to_string(scene.animation.height);
    tracer::Renderer renderer = naming_out_of_memory("setting up the render", [&] {
        return last_use ? tracer::Renderer(scene, settings, tracer::Renderer::ReleaseRecords{})
                        : tracer::Renderer(scene, settings);
    });
    ModeRun run;
    for (const int frame : frames) {
        const auto began = std::chrono::steady_clock::now();
        tracer::Image image = naming_out_of_memory(
            "rendering frame " + std::to_string(frame) + " (" + size + " pixels)",
            [&] { return renderer.render_frame(frame); });
        if (progress) progress->frame_done(renderer.last_sample_count());
        if (write)
            tracer::write_image(image, tracer::frame_path(pattern, frame), args.output_variant);
        if (sink) sink(frame, image);
        const double pixels = double(image.width) * image.height;
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
        run.frames.push_back({frame, seconds, double(renderer.last_sample_count()) / pixels,
                              renderer.last_estimate(), renderer.last_tiles_over_target()});
        if (const auto& estimate = renderer.last_estimate(); estimate && write) {
            if (progress) progress->clear();
            char line[160];
            std::snprintf(
                line, sizeof line,
                "frame %d: %.3f s, %.1f samples per pixel, estimated RMSE %.3g (linear light)",
                frame, seconds, run.frames.back().mean_samples, estimate->rmse);
            err << line << "; worst " << tracer::FrameEstimate::kTile << "-pixel tiles";
            for (std::size_t k = 0; k < estimate->worst.size(); ++k) {
                std::snprintf(line, sizeof line, "%s %.3g at (%d, %d)", k ? "," : "",
                              estimate->worst[k].rmse, estimate->worst[k].x, estimate->worst[k].y);
                err << line;
            }
            if (estimate->photon_rmse > 0.0) {
                std::snprintf(line, sizeof line,
                              "; the photon map's RMSE %.3g (not lowered by samples)",
                              estimate->photon_rmse);
                err << line;
            }
            if (const int over = renderer.last_tiles_over_target())
                err << "; " << over << " of " << renderer.last_tile_count()
                    << " tiles reached --spp " << sampling.samples << " above the target "
                    << sampling.target_error;
            err << "\n";
        }
        if (write && args.error_image) {
            // Per pixel its estimated RMSE, grey.
            tracer::Image errors(image.width, image.height);
            const std::vector<double>& squared = renderer.last_squared_error();
            for (int y = 0; y < image.height; ++y)
                for (int x = 0; x < image.width; ++x)
                    errors.set(x, y,
                               glm::dvec3(std::sqrt(squared[std::size_t(y) * image.width + x])));
            tracer::write_image(errors, tracer::frame_path(*args.error_image, frame));
        }
        if (write && args.samples_image) {
            // Per pixel its samples over the ceiling, grey: white took all.
            tracer::Image taken(image.width, image.height);
            const std::vector<int>& samples = renderer.last_samples();
            for (int y = 0; y < image.height; ++y)
                for (int x = 0; x < image.width; ++x)
                    taken.set(x, y,
                              glm::dvec3(double(samples[std::size_t(y) * image.width + x]) /
                                         sampling.samples));
            tracer::write_image(taken, tracer::frame_path(*args.samples_image, frame));
        }
        if (keep) keep->push_back(std::move(image));
    }
    if (progress) progress->clear();
    renderer.measure_memory();
    // The render's peak, before counting a full build adds its own.
    const double peak_mb = peak_resident_mb();
    if (settings.build.count_full) renderer.count_full_hierarchy();
    run.counters = renderer.counters();
    run.counters.memory_start_mb = start_mb;
    run.counters.memory_peak_mb = peak_mb;
    return run;
}

}  // namespace hexant::app
