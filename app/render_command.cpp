#include "app/render_command.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

#include <sys/resource.h>
#include <unistd.h>

#include "app/out_of_memory.hpp"
#include "image/image_format.hpp"
#include "language/interpreter.hpp"
#include "runtime/objects/object_error.hpp"
#include "tracer/gif_animation.hpp"
#include "tracer/image_output.hpp"
#include "tracer/renderer.hpp"
#include "tracer/whole_file.hpp"

namespace hexant::app {

namespace {

using tracer::Counters;

}  // namespace

std::vector<int> window_frames(const std::string& text, const std::vector<int>& frames) {
    const auto slash = text.find('/');
    const auto digits = [](const std::string& t) {
        return !t.empty() && t.size() <= 18 &&
               t.find_first_not_of("0123456789") == std::string::npos;
    };
    const std::string i_text = slash == std::string::npos ? text : text.substr(0, slash);
    const std::string n_text = slash == std::string::npos ? "" : text.substr(slash + 1);
    if (slash == std::string::npos || !digits(i_text) || !digits(n_text))
        throw std::runtime_error(
            "--window: expected I/N (window I of N, I from 0 to N-1, whole numbers), got '" + text +
            "'");
    const unsigned long long i = std::stoull(i_text), n = std::stoull(n_text);
    if (n < 1 || i >= n)
        throw std::runtime_error("--window " + text +
                                 ": I must lie from 0 to N-1 and N be at least 1");
    const unsigned long long k = frames.size();
    // Window i holds frames [floor(i k / n), floor((i + 1) k / n)), in 128
    // bits (i k overflows 64 for windows counted in the billions).
    const auto begin = static_cast<std::size_t>(static_cast<unsigned __int128>(i) * k / n);
    const auto end = static_cast<std::size_t>(static_cast<unsigned __int128>(i + 1) * k / n);
    return {frames.begin() + static_cast<std::ptrdiff_t>(begin),
            frames.begin() + static_cast<std::ptrdiff_t>(end)};
}

namespace {

// The frames to render, in increasing order: "A:B", "A", or a comma list of
// those ("1,17,33", "1:4,9").
std::vector<int> frame_selection(const std::optional<std::string>& text,
                                 const runtime::Animation& a) {
    std::vector<int> frames;
    if (!text) {
        for (int k = a.initial_frame; k <= a.final_frame; ++k) frames.push_back(k);
        return frames;
    }
    std::stringstream items(*text + ",");  // every item ends with a comma
    std::string item;
    while (std::getline(items, item, ',')) {
        const auto colon = item.find(':');
        int first = 0, last = 0;
        try {
            std::size_t used = 0, used_last = 0;
            first = last = std::stoi(item, &used);
            if (colon != std::string::npos) last = std::stoi(item.substr(colon + 1), &used_last);
            if ((colon == std::string::npos ? used : colon + 1 + used_last) != item.size() ||
                (colon != std::string::npos && used != colon))
                throw std::invalid_argument(item);
        } catch (const std::exception&) {
            throw std::runtime_error("--frames: expected A:B, A or a comma list of those, got '" +
                                     *text + "'");
        }
        if (first > last)
            throw std::runtime_error("--frames " + *text + ": " + std::to_string(first) + ":" +
                                     std::to_string(last) + " runs backwards (A:B needs A <= B)");
        if (first < a.initial_frame || last > a.final_frame)
            throw std::runtime_error("--frames " + *text + ": the animation has frames " +
                                     std::to_string(a.initial_frame) + " to " +
                                     std::to_string(a.final_frame));
        for (int k = first; k <= last; ++k) frames.push_back(k);
    }
    if (frames.empty()) throw std::runtime_error("--frames: no frame named in '" + *text + "'");
    std::sort(frames.begin(), frames.end());
    frames.erase(std::unique(frames.begin(), frames.end()), frames.end());
    return frames;
}

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
    {"objects", [](const Counters& c) { return double(c.objects); }, 0},
    {"bounds built", [](const Counters& c) { return double(c.bounds_built); }, 0},
    {"hierarchy cells", [](const Counters& c) { return double(c.cells); }, 0},
    {"cells of a full build", [](const Counters& c) { return double(c.cells_full); }, 0},
    {"box nodes", [](const Counters& c) { return double(c.box_nodes); }, 0},
    {"linear-motion nodes", [](const Counters& c) { return double(c.motion_nodes); }, 0},
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

// What --stats-json records of each frame (keys none of the rows use, so
// a tool that greps one row's name finds the row).
struct FrameRecord {
    int frame = 0;
    double seconds = 0.0;       // rendering it, its file written
    double mean_samples = 0.0;  // samples per pixel, over the frame
    std::optional<tracer::FrameEstimate> estimate;
    int tiles_over_target = 0;  // (adaptive sampling: at the ceiling, above the target)
};

struct ModeRun {
    Counters counters;
    std::vector<FrameRecord> frames;
};

void print_stats(std::ostream& out, const std::vector<std::pair<std::string, Counters>>& columns) {
    out << std::left << std::setw(26) << "";
    for (const auto& c : columns) out << std::right << std::setw(16) << c.first;
    // The paper's ratio column: the second column over the first
    // (spacetime to frame-by-frame).
    if (columns.size() == 2) out << std::setw(10) << "ratio";
    out << "\n";
    for (const Row& row : kRows) {
        out << std::left << std::setw(26) << row.name;
        for (const auto& c : columns)
            out << std::right << std::setw(16) << std::fixed << std::setprecision(row.decimals)
                << row.value(c.second);
        if (columns.size() == 2) {
            const double a = row.value(columns[0].second), b = row.value(columns[1].second);
            out << std::setw(10) << std::setprecision(2);
            if (a > 0.0)
                out << b / a;
            else
                out << "-";
        }
        out << "\n";
    }
}

// A JSON number, or null for what JSON cannot hold (an infinite estimate
// of a frame whose colours overflow).
std::string json_number(double v) {
    if (!std::isfinite(v)) return "null";
    std::ostringstream out;
    out << std::setprecision(17) << v;
    return out.str();
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

// One full render in one mode; frames go to files as they finish.
// With last_use, each of the scene's object records is freed as soon as the
// renderer has made its intelligent objects of it (about 2 KB a parsed
// object, as much as the object: records and objects are never all held
// at once).
// The progress line on a terminal: the frame, the frames done of all, the
// samples per second so far and the time left at that pace.
class ProgressLine {
  public:
    explicit ProgressLine(std::size_t frames) : frames_(frames), start_(Clock::now()) {}
    void update(int frame, double fraction, std::uint64_t frame_samples) {
        const auto now = Clock::now();
        if (now - shown_ < std::chrono::milliseconds(100) && fraction < 1.0) return;
        shown_ = now;
        const double elapsed = std::chrono::duration<double>(now - start_).count();
        const double done = double(done_) + fraction;
        char line[160];
        std::snprintf(
            line, sizeof line, "\rframe %d (%zu of %zu done): %3d%%, %.2f M samples/s, %s left ",
            frame, done_, frames_, int(fraction * 100.0),
            elapsed > 0.0 ? double(samples_ + frame_samples) / elapsed * 1e-6 : 0.0,
            done > 0.0 ? duration(elapsed / done * (double(frames_) - done)).c_str() : "?");
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
    std::size_t frames_, done_ = 0, width_ = 0;
    std::uint64_t samples_ = 0;
    Clock::time_point start_, shown_{};
};

// One full render in one mode; frames go to files as they finish.
// With last_use, each of the scene's object records is freed as soon as the
// renderer has made its intelligent objects of it (about 2 KB a parsed
// object, as much as the object: records and objects are never all held
// at once).
ModeRun render_mode(runtime::SceneDescription& scene, const RenderArguments& args,
                    const Sampling& sampling, tracer::Mode mode, const std::string& pattern,
                    const std::vector<int>& frames, bool write, std::vector<tracer::Image>* keep,
                    bool last_use, std::ostream& err) {
    tracer::RenderSettings settings;
    settings.mode = mode;
    settings.samples_per_pixel = sampling.samples;
    settings.sample_sets = sampling.sets;
    settings.target_error = sampling.target_error;
    settings.jitter = !args.no_jitter;
    settings.sample_seed = args.seed;
    settings.threads = args.threads;
    if (args.light_speed) settings.light_speed = *args.light_speed;
    settings.build = args.hierarchy.options();
    settings.first_frame = frames.front();
    settings.last_frame = frames.back();
    settings.build.count_full = args.stats || args.compare || args.stats_json.has_value();
    std::optional<ProgressLine> progress;
    if (isatty(STDERR_FILENO)) {
        progress.emplace(frames.size());
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
        if (write) tracer::write_image(image, tracer::frame_path(pattern, frame));
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

}  // namespace

void add_render_arguments(CLI::App& command, RenderArguments& a) {
    add_scene_arguments(command, a.scene);
    command.add_option("--mode", a.mode,
                       "spacetime (default), frames (per-frame hierarchies) or brute");
    command
        .add_option(
            "--spp", a.samples_per_pixel,
            "Samples per pixel, or with --target-error their ceiling (default: --target-error "
            "1/128 under 256; with --no-jitter 1)")
        ->check(CLI::Range(1, 1 << 20));
    command.add_flag("--no-jitter", a.no_jitter,
                     "Samples at the centres of their strata (with --spp 1: the pixel centre)");
    command.add_option("--seed", a.seed,
                       "Scramble the samples with this number (default 0); another seed gives "
                       "an independent estimate of the same image");
    command.add_flag(
        "--error-estimate", a.error_estimate,
        "Estimate each frame's error without a reference: its samples are two independent "
        "halves (an even --spp), and the RMSE of their mean is printed with the worst tiles");
    command.add_option(
        "--error-image", a.error_image,
        "Also write each frame's per-pixel estimated RMSE (linear light) as an image; #### "
        "becomes the frame number (implies --error-estimate)");
    command.add_option_function<std::string>(
        "--target-error",
        [&a](const std::string& text) { a.target_error = parse_target_error(text); },
        "Adaptive sampling: each 16-pixel tile doubles its samples until its estimated RMSE "
        "(linear light, 0 to 1; a number or a fraction such as 1/128) is at most this, with --spp "
        "the ceiling "
        "(default: without --spp, 1/128 under 256)");
    command.add_option(
        "--samples-image", a.samples_image,
        "Also write the samples each pixel took, over --spp, as a grey image; #### becomes the "
        "frame number");
    command.add_option("--frames", a.frames,
                       "A:B renders frames A to B of the animation; a comma list (1,17,33 or "
                       "1:4,9) renders those");
    command.add_option(
        "--window", a.window,
        "I/N renders the I-th (0 to N-1, a Slurm array task's number) of N consecutive windows of "
        "the frames, each with a hierarchy over its own time only; the frames are those one run "
        "over all would write");
    command.add_flag("--resume", a.resume,
                     "Skip frames already written (POV-Ray's +C) and remove what a killed run left "
                     "half-written");
    command.add_option("-o,--output", a.output,
                       "Frame file pattern; #### becomes the frame number (default "
                       "out/SCENE/frame_####.png): .png is 8-bit sRGB, .exr linear float");
    command.add_option("--contact-sheet", a.contact_sheet,
                       "Also write the frames as one grid image");
    command.add_option("--animation", a.animation, "Also write an animated GIF of the frames");
    command.add_flag("--stats", a.stats, "Print the paper's table rows for the run");
    command.add_option("--stats-json", a.stats_json, "Write the same figures as JSON");
    command.add_flag("--compare", a.compare,
                     "Render in spacetime and frames modes and print both columns and their ratio");
    command.add_option("--threads", a.threads, "Worker threads (default 0: all cores)")
        ->check(CLI::NonNegativeNumber);
    command.add_option_function<std::string>(
        "--light-speed",
        [&a](const std::string& text) {
            // (strtod: a subnormal speed is a speed; stod refuses it.)
            char* end = nullptr;
            double value = std::strtod(text.c_str(), &end);
            if (text.empty() || end != text.c_str() + text.size())
                value = std::numeric_limits<double>::quiet_NaN();
            if (!(value > 0.0))
                throw CLI::ValidationError("--light-speed",
                                           "'" + text +
                                               "' is not a positive number of scene units per "
                                               "clock unit (inf: instant light)");
            a.light_speed = value;
        },
        "Finite speed of light, scene units per clock unit: every ray runs back in time as it "
        "goes, so a fast "
        "object is seen where it was when its light left it (default: instant)");
    add_hierarchy_arguments(command, a.hierarchy);
}

namespace {

// Every name the run will write, checked before any frame is rendered: the
// patterns (frame_path's rules), each name's format, a GIF's 16-bit sides,
// a folder that can be made for each, and no two outputs naming one file (a
// contact sheet named as a frame, or the stats as a samples image, would
// replace it). Errors name the flag.
void check_outputs(const RenderArguments& args, const std::string& pattern,
                   const std::vector<int>& selected, const runtime::Animation& animation) {
    struct Output {
        std::string flag, name;
        bool per_frame;  // a pattern with #### (one file per frame)
        enum class Kind { Image, Animation, Text } kind;
    };
    std::vector<Output> outputs{{"-o", pattern, true, Output::Kind::Image}};
    if (args.error_image)
        outputs.push_back({"--error-image", *args.error_image, true, Output::Kind::Image});
    if (args.samples_image)
        outputs.push_back({"--samples-image", *args.samples_image, true, Output::Kind::Image});
    if (args.contact_sheet)
        outputs.push_back({"--contact-sheet", *args.contact_sheet, false, Output::Kind::Image});
    if (args.animation)
        outputs.push_back({"--animation", *args.animation, false, Output::Kind::Animation});
    if (args.stats_json)
        outputs.push_back({"--stats-json", *args.stats_json, false, Output::Kind::Text});
    const auto file_of = [&](const Output& o, int frame) {
        return std::filesystem::absolute(o.per_frame ? tracer::frame_path(o.name, frame) : o.name)
            .lexically_normal();
    };
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        const Output& o = outputs[i];
        const auto named = [&](const std::function<void()>& check) {
            try {
                check();
            } catch (const std::exception& e) {
                const std::string what = e.what();
                throw std::runtime_error(what.rfind(o.flag, 0) == 0 ? what : o.flag + " " + what);
            }
        };
        if (o.name.empty()) throw std::runtime_error(o.flag + ": an empty file name");
        named([&] {
            if (o.per_frame) tracer::check_frame_pattern(o.name, selected.size(), o.flag);
            if (o.kind == Output::Kind::Image) tracer::check_image_name(o.name);
            if (o.kind == Output::Kind::Animation) tracer::check_animation_name(o.name);
        });
        // (A folder that could not be made fails now, not after the first
        // frame: its nearest existing ancestor must be a folder this
        // process may write in. Nothing is made before the render.)
        std::filesystem::path folder = file_of(o, selected.front()).parent_path();
        std::error_code error;
        while (!std::filesystem::exists(folder, error) && folder.has_parent_path() &&
               folder != folder.parent_path())
            folder = folder.parent_path();
        if (!std::filesystem::is_directory(folder, error) ||
            access(folder.c_str(), W_OK | X_OK) != 0)
            throw std::runtime_error(o.flag + " " + o.name + ": cannot write in " +
                                     folder.string());
        for (std::size_t j = 0; j < i; ++j)
            for (const int frame : selected) {
                if (file_of(o, frame) != file_of(outputs[j], frame)) continue;
                throw std::runtime_error(o.name + ": " + o.flag + " names " +
                                         (j == 0 ? "frame " + std::to_string(frame) + "'s file"
                                                 : outputs[j].flag + "'s file" +
                                                       (o.per_frame || outputs[j].per_frame
                                                            ? " for frame " + std::to_string(frame)
                                                            : "")));
            }
    }
    if (args.animation && std::max(animation.width, animation.height) > tracer::kGifMaxSide)
        throw std::runtime_error(
            *args.animation + ": a GIF is at most " + std::to_string(tracer::kGifMaxSide) +
            " pixels a side; the frames are " + std::to_string(animation.width) + " by " +
            std::to_string(animation.height));
}

}  // namespace

void apply_scene_defaults(const RenderArguments& args, runtime::SceneDescription& scene,
                          std::ostream& err) {
    const auto& g = scene.global;
    if (!g.motion_blur_samples) return;
    // MegaPOV's motion_blur SAMPLES, TIME: TIME is how long (in clock
    // units) the shutter is open; hexant's --shutter is that over the
    // clock step between frames.
    err << "note: MegaPOV's motion_blur " << *g.motion_blur_samples << ", " << *g.motion_blur_time
        << ": hexant blurs every render;";
    if (!args.samples_per_pixel) err << " --spp " << *g.motion_blur_samples;
    const double step = std::fabs(scene.animation.clock_delta());
    if (!args.scene.shutter && scene.animation.clock_runs() && step > 0.0 && std::isfinite(step)) {
        scene.animation.shutter = std::clamp(*g.motion_blur_time / step, 0.0, 1.0);
        err << " --shutter " << scene.animation.shutter;
    }
    err << " by default\n";
}

double parse_target_error(const std::string& text) {
    // A number, or A/B (the README's 1/128).
    double value = std::numeric_limits<double>::quiet_NaN();
    try {
        std::size_t used = 0;
        value = std::stod(text, &used);
        if (used < text.size() && text[used] == '/') {
            std::size_t more = 0;
            const std::string rest = text.substr(used + 1);
            value /= std::stod(rest, &more);
            used += 1 + more;
        }
        if (used != text.size()) value = std::numeric_limits<double>::quiet_NaN();
    } catch (const std::exception&) {
        value = std::numeric_limits<double>::quiet_NaN();
    }
    if (!(value > 0.0) || !std::isfinite(value))
        throw CLI::ValidationError("--target-error",
                                   "expected a positive number (an RMSE in linear light, e.g. "
                                   "0.01 or 1/128), got '" +
                                       text + "'");
    return value;
}

Sampling resolve_sampling(const RenderArguments& args, const runtime::SceneDescription& scene) {
    if (args.target_error && !(*args.target_error > 0.0 && std::isfinite(*args.target_error)))
        throw std::runtime_error(
            "--target-error: expected a positive number (an RMSE in linear light)");
    Sampling s;
    const std::optional<int> asked =
        args.samples_per_pixel ? args.samples_per_pixel : scene.global.motion_blur_samples;
    if (!asked && !args.no_jitter && !args.target_error) {
        s.samples = kDefaultCeiling;
        s.target_error = kDefaultTargetError;
    } else {
        s.samples = asked.value_or(args.target_error ? kDefaultCeiling : 1);
        s.target_error = args.target_error.value_or(0.0);
    }
    const bool estimated = s.target_error > 0.0 || args.error_estimate || args.error_image;
    if (!estimated) return s;
    if (s.samples < 2 || s.samples % 2 != 0 || args.no_jitter) {
        const char* flags =
            args.target_error ? "--target-error needs" : "--error-estimate and --error-image need";
        const std::string given = args.samples_per_pixel ? "--spp is " + std::to_string(s.samples)
                                  : asked
                                      ? "the scene's motion_blur gives " + std::to_string(s.samples)
                                      : "the default ceiling is " + std::to_string(s.samples);
        throw std::runtime_error(
            std::string(flags) +
            " an even --spp of 2 or more (two independent halves) and jitter; " + given +
            (args.no_jitter ? ", with --no-jitter" : ""));
    }
    s.sets = 2;
    return s;
}

void check_render_plan(const RenderArguments& args, const std::filesystem::path& scene_file,
                       const runtime::SceneDescription& scene) {
    const std::vector<int> selected = frame_selection(args.frames, scene.animation);
    const std::string pattern =
        args.output ? *args.output : "out/" + scene_file.stem().string() + "/frame_####.png";
    if (args.window && (args.contact_sheet || args.animation || args.compare))
        throw std::runtime_error(
            "--window renders part of the frames: --contact-sheet, --animation and --compare "
            "need them all (join the windows' frames with --resume and those outputs)");
    if (args.resume && args.compare)
        throw std::runtime_error("--resume skips frames --compare would measure");
    (void)resolve_sampling(args, scene);
    check_outputs(args, pattern, selected, scene.animation);
}

int run_render(const RenderArguments& args, std::ostream& out, std::ostream& err) {
    return run_reporting_errors(err, [&] {
        ResolvedScene resolved = resolve(args.scene);
        for (const auto& warning : resolved.warnings) err << warning << "\n";
        // The scene's files go beside its images.
        if (args.output) {
            const std::filesystem::path folder = std::filesystem::path(*args.output).parent_path();
            resolved.options.output_folder = folder.empty() ? std::filesystem::path(".") : folder;
        }
        runtime::SceneDescription scene =
            language::parse_scene_file(resolved.scene, resolved.options);
        apply_scene_defaults(args, scene, err);
        const Sampling sampling = resolve_sampling(args, scene);
        std::vector<int> selected = frame_selection(args.frames, scene.animation);
        std::vector<int> written;  // (--resume: frames already on disk)
        const std::string pattern =
            args.output ? *args.output
                        : "out/" + resolved.scene.stem().string() + "/frame_####.png";
        if (args.window && (args.contact_sheet || args.animation || args.compare))
            throw std::runtime_error(
                "--window renders part of the frames: --contact-sheet, --animation and --compare "
                "need them all (join the windows' frames with --resume and those outputs)");
        if (args.resume && args.compare)
            throw std::runtime_error("--resume skips frames --compare would measure");
        if (args.window) {
            selected = window_frames(*args.window, selected);
            if (selected.empty()) {
                out << "window " << *args.window << ": no frames (more windows than frames)\n";
                // (Its statistics: none, for a merge of every window's.)
                if (args.stats_json)
                    write_stats_json(
                        *args.stats_json,
                        {{tracer::mode_name(tracer::parse_mode(args.mode)), ModeRun{}}});
                return 0;
            }
        }
        check_outputs(args, pattern, selected, scene.animation);
        if (args.resume) {
            // A frame on disk was written whole (a temporary renamed over
            // it); what a killed run left half-written is its temporaries.
            int leftovers = 0;
            std::vector<int> missing;
            for (const int frame : selected) {
                const std::filesystem::path path = tracer::frame_path(pattern, frame);
                leftovers += tracer::remove_leftover_temporaries(path);
                std::error_code error;
                if (!std::filesystem::is_regular_file(path, error)) {
                    missing.push_back(frame);
                    continue;
                }
                // A file hexant did not write whole, or of another size (an
                // earlier render with other flags), is rendered again.
                std::string why;
                try {
                    const image::StoredImage stored = image::read_stored_image(path);
                    if (stored.width != scene.animation.width ||
                        stored.height != scene.animation.height)
                        why = std::to_string(stored.width) + " by " +
                              std::to_string(stored.height) + " pixels, not " +
                              std::to_string(scene.animation.width) + " by " +
                              std::to_string(scene.animation.height);
                } catch (const std::exception& e) {
                    why = e.what();
                }
                if (!why.empty()) {
                    err << "--resume: " << path.string() << " is rendered again (" << why << ")\n";
                    missing.push_back(frame);
                }
            }
            if (leftovers > 0)
                err << "--resume: removed " << leftovers << " half-written temporar"
                    << (leftovers == 1 ? "y" : "ies") << "\n";
            out << "--resume: " << selected.size() - missing.size() << " of " << selected.size()
                << " frames already written\n";
            written.assign(selected.begin(), selected.end());
            std::erase_if(written, [&](int frame) {
                return std::binary_search(missing.begin(), missing.end(), frame);
            });
            if (missing.empty() && !args.contact_sheet && !args.animation) return 0;
            selected = std::move(missing);
        }
        const bool keep_frames = args.contact_sheet || args.animation;
        std::vector<tracer::Image> frames;
        std::vector<std::pair<std::string, ModeRun>> columns;
        const tracer::Mode mode =
            args.compare ? tracer::Mode::Spacetime : tracer::parse_mode(args.mode);
        if (!selected.empty())
            columns.emplace_back(tracer::mode_name(mode),
                                 render_mode(scene, args, sampling, mode, pattern, selected, true,
                                             keep_frames ? &frames : nullptr, !args.compare, err));
        if (keep_frames && !written.empty()) {
            // (--resume) The frames on disk join those just rendered, in
            // order, read back as written (an 8-bit sRGB frame gives its
            // very bytes again).
            std::vector<std::pair<int, tracer::Image>> all;
            for (std::size_t i = 0; i < selected.size(); ++i)
                all.emplace_back(selected[i], std::move(frames[i]));
            for (const int frame : written)
                all.emplace_back(frame, tracer::read_image(tracer::frame_path(pattern, frame)));
            std::sort(all.begin(), all.end(),
                      [](const auto& a, const auto& b) { return a.first < b.first; });
            frames.clear();
            for (auto& [frame, image] : all) frames.push_back(std::move(image));
        }
        if (args.compare)  // the paper's order: frame by frame, then spacetime
            columns.emplace(columns.begin(), "frames",
                            render_mode(scene, args, sampling, tracer::Mode::Frames, pattern,
                                        selected, false, nullptr, true, err));
        if (selected.empty()) {
            out << "frames: none rendered (all written already)\n";
        } else {
            const int first = selected.front(), last = selected.back();
            const bool contiguous = last - first + 1 == static_cast<int>(selected.size());
            out << "frames ";
            if (contiguous) {
                out << first << " to " << last << ": " << tracer::frame_path(pattern, first)
                    << (last > first ? " ... " + tracer::frame_path(pattern, last) : "") << "\n";
            } else {
                for (std::size_t i = 0; i < selected.size(); ++i)
                    out << (i ? ", " : "") << selected[i];
                out << ": " << tracer::frame_path(pattern, first) << " ... "
                    << tracer::frame_path(pattern, last) << "\n";
            }
        }
        if (args.contact_sheet) {
            tracer::write_image(naming_out_of_memory("making the contact sheet",
                                                     [&] { return tracer::contact_sheet(frames); }),
                                *args.contact_sheet);
            out << "contact sheet: " << *args.contact_sheet << "\n";
        }
        if (args.animation) {
            tracer::write_animation(frames, *args.animation);
            out << "animation: " << *args.animation << "\n";
        }
        if ((args.stats || args.compare) && !columns.empty()) {
            std::vector<std::pair<std::string, Counters>> counters;
            for (const auto& [name, run] : columns) counters.emplace_back(name, run.counters);
            print_stats(out, counters);
        }
        if (args.stats_json) write_stats_json(*args.stats_json, columns);
        return 0;
    });
}

}  // namespace hexant::app
