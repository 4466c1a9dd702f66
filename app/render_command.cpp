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
#include <sys/stat.h>
#include <unistd.h>

#include "app/mode_run.hpp"
#include "app/out_of_memory.hpp"
#include "app/povray_render_options.hpp"
#include "app/resume.hpp"
#include "app/scene_reading.hpp"
#include "image/image_format.hpp"
#include "language/interpreter.hpp"
#include "runtime/objects/object_error.hpp"
#include "tracer/gif_animation.hpp"
#include "tracer/image_output.hpp"
#include "tracer/renderer.hpp"
#include "tracer/video_file.hpp"
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
        "Print each frame's error estimated without a reference (from blocks of each pixel's "
        "samples) with its worst tiles: on whenever --spp is 2 or more with jitter; this flag "
        "refuses a render that cannot estimate");
    command.add_option(
        "--error-image", a.error_image,
        "Also write each frame's per-pixel estimated RMSE (linear light) as an image; #### "
        "becomes the frame number (implies --error-estimate)");
    command.add_option_function<std::string>(
        "--target-error",
        [&a](const std::string& text) { a.target_error = parse_target_error(text); },
        "Adaptive sampling: each frame samples until its estimated RMSE (linear light, "
        "0 to 1; a number or a fraction such as 1/128) is at most this, each pixel as many "
        "samples as its error and cost call for, with --spp the ceiling (default: without "
        "--spp, 1/128 under 256)");
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
    command
        .add_flag("--resume{check}", a.resume_text,
                  "Keep the frames already written by this same render (their records say the "
                  "same scene, files and settings made them), render the others, and remove what "
                  "a killed run left half-written; --resume=keep keeps any readable frame of the "
                  "right size, as POV-Ray's +C")
        ->check(CLI::IsMember({"check", "keep"}))
        ->each([&a](const std::string& how) {
            a.resume = true;
            a.resume_keep = how == "keep";
        });
    command.add_option("-o,--output", a.output,
                       "Frame file pattern; #### becomes the frame number (default "
                       "out/SCENE/frame_####.png): .png is 8-bit sRGB, .exr linear float; "
                       ".tga, .ppm, .bmp, .tif 8-bit sRGB, .hdr linear RGBE");
    command.add_option("--contact-sheet", a.contact_sheet,
                       "Also write the frames as one grid image");
    command.add_option("--animation", a.animation, "Also write an animated GIF of the frames");
    command.add_option("--video", a.video,
                       "Also write a video of the frames, each added as it finishes: .mp4 "
                       "(H.264, CRF 18) or .webm (VP9, CRF 24), 4:2:0, BT.709");
    command.add_option_function<std::string>(
        "--fps",
        [&a](const std::string& text) {
            char* end = nullptr;
            double value = std::strtod(text.c_str(), &end);
            if (text.empty() || end != text.c_str() + text.size())
                value = std::numeric_limits<double>::quiet_NaN();
            if (!(value > 0.0 && value <= 1000.0))
                throw CLI::ValidationError(
                    "--fps", "'" + text +
                                 "' is not a frame rate (frames per second, above 0, at "
                                 "most 1000)");
            a.fps = value;
        },
        "Frames per second of --video and --animation (default 24)");
    command.add_flag("--stats", a.stats, "Print the paper's table rows for the run");
    command.add_option("--stats-json", a.stats_json, "Write the same figures as JSON");
    command.add_flag("--stats-full", a.stats_full,
                     "Also count the cells a full build would make (implies --stats without "
                     "--stats-json): builds what the lazy build left, after the render, which on "
                     "a large scene takes about as long as the render");
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
    command.add_option_function<std::string>(
        "--gi",
        [&a](const std::string& text) {
            if (text != "cache" && text != "path")
                throw CLI::ValidationError("--gi", "'" + text + "' is not cache or path");
            a.gi_path = text == "path";
        },
        "Radiosity's indirect light: cache (default) as POV-Ray 3.7 computes it, an irradiance "
        "cache filled by a pretrace for each frame; path: one gathering ray per sample and "
        "bounce, at the sample's own time (unbiased: it converges with the samples, moves with "
        "its objects and does not change from frame to frame where nothing moves)");
    add_hierarchy_arguments(command, a.hierarchy);
}

namespace {

// Every name the run will write, checked before any frame is rendered: the
// patterns (frame_path's rules), each name's format, a GIF's 16-bit sides,
// a folder that can be made for each, and no two outputs naming one file (a
// contact sheet named as a frame, or the stats as a samples image, would
// replace it). Errors name the flag.
void check_outputs(const RenderArguments& args, const std::string& pattern,
                   const std::vector<int>& selected, const runtime::Animation& animation,
                   const std::vector<std::filesystem::path>& inputs) {
    struct Output {
        std::string flag, name;
        bool per_frame;  // a pattern with #### (one file per frame)
        enum class Kind { Image, Animation, Video, Text } kind;
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
    if (args.video) outputs.push_back({"--video", *args.video, false, Output::Kind::Video});
    if (args.stats_json)
        outputs.push_back({"--stats-json", *args.stats_json, false, Output::Kind::Text});
    const auto file_of = [&](const Output& o, int frame) {
        return std::filesystem::absolute(o.per_frame ? tracer::frame_path(o.name, frame) : o.name)
            .lexically_normal();
    };
    // The inputs' device and inode, once (an output is the same file by any
    // name, a hard link too: one stat of it per frame, not two per input).
    std::vector<std::pair<std::filesystem::path, struct stat>> input_ids;
    for (const auto& input : inputs) {
        struct stat id {};
        if (::stat(input.c_str(), &id) == 0) input_ids.emplace_back(input, id);
    }
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
            if (o.kind == Output::Kind::Image) {
                // Each per-frame image is a frame's size; the contact sheet
                // its grid's.
                const auto [width, height] =
                    o.per_frame ? std::pair{animation.width, animation.height}
                                : tracer::contact_sheet_size(int(selected.size()), animation.width,
                                                             animation.height);
                tracer::check_image_size(o.name, width, height);
            }
            if (o.kind == Output::Kind::Animation) tracer::check_animation_name(o.name);
            // (Its extension, even sides for H.264, FFmpeg and its encoder.)
            if (o.kind == Output::Kind::Video)
                tracer::check_video_output(o.name, animation.width, animation.height);
            // A link, device, FIFO or folder in an output's place is
            // refused now, not after the render (whole_file.hpp).
            // Nor one of the scene's own inputs (its image_map, an include):
            // it would be replaced (issue 45), the same file by any name.
            for (const int frame : selected) {
                const std::filesystem::path file = file_of(o, frame);
                tracer::TemporaryFile::refuse_other_than_regular(file);
                struct stat here {};
                if (::stat(file.c_str(), &here) == 0)
                    for (const auto& [input, where] : input_ids)
                        if (where.st_dev == here.st_dev && where.st_ino == here.st_ino)
                            throw std::runtime_error(
                                o.flag + " " + file.string() + " is one of the scene's inputs (" +
                                input.string() + "): refused, it would be replaced");
                if (!o.per_frame) break;
            }
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
    // (--gi chooses how radiosity is computed: nothing to choose without it.)
    if (args.gi_path && !g.radiosity.enabled)
        err << "note: --gi path: the scene has no radiosity { }, so it changes nothing\n";
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
    // A number, or A/B (the README's 1/128); decimal only (std::stod
    // would read "0x10" as 16).
    double value = std::numeric_limits<double>::quiet_NaN();
    try {
        if (text.find_first_not_of("0123456789.eE+-/") != std::string::npos)
            throw std::invalid_argument("not a decimal number");
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
    if (s.samples < 2 || args.no_jitter) {
        const char* flags =
            args.target_error ? "--target-error needs" : "--error-estimate and --error-image need";
        const std::string given = args.samples_per_pixel ? "--spp is " + std::to_string(s.samples)
                                  : asked
                                      ? "the scene's motion_blur gives " + std::to_string(s.samples)
                                      : "the default ceiling is " + std::to_string(s.samples);
        throw std::runtime_error(
            std::string(flags) +
            " a --spp of 2 or more and jitter (the estimate compares blocks of each pixel's "
            "samples); " +
            given + (args.no_jitter ? ", with --no-jitter" : ""));
    }
    return s;
}

void check_render_plan(const RenderArguments& args, const std::filesystem::path& scene_file,
                       const runtime::SceneDescription& scene) {
    const std::vector<int> selected = frame_selection(args.frames, scene.animation);
    const std::string pattern =
        args.output ? *args.output : "out/" + scene_file.stem().string() + "/frame_####.png";
    if (args.window && (args.contact_sheet || args.animation || args.video || args.compare))
        throw std::runtime_error(
            "--window renders part of the frames: --contact-sheet, --animation, --video and "
            "--compare need them all (join the windows' frames with --resume and those outputs)");
    if (args.resume && args.compare)
        throw std::runtime_error("--resume skips frames --compare would measure");
    (void)resolve_sampling(args, scene);
    check_outputs(args, pattern, selected, scene.animation, scene.inputs);
}

int run_render(const RenderArguments& given, std::ostream& out, std::ostream& err) {
    return run_reporting_errors(err, [&] {
        ResolvedScene resolved = resolve(given.scene);
        for (const auto& warning : resolved.warnings) err << warning << "\n";
        // POV-Ray's switches and .ini options, as the flags they stand for.
        std::vector<std::string> notes;
        const RenderArguments args = with_povray_options(given, resolved, notes);
        for (const auto& note : notes) err << "note: " << note << "\n";
        // The scene's files go beside its images.
        if (args.output) {
            const std::filesystem::path folder = std::filesystem::path(*args.output).parent_path();
            resolved.options.output_folder = folder.empty() ? std::filesystem::path(".") : folder;
        }
        SceneReading reading(resolved, err);
        runtime::SceneDescription& scene = reading.scene();
        apply_scene_defaults(args, scene, err);
        const Sampling sampling = resolve_sampling(args, scene);
        std::vector<int> selected = frame_selection(args.frames, scene.animation);
        std::vector<int> written;  // (--resume: frames already on disk)
        const std::string pattern =
            args.output ? *args.output
                        : "out/" + resolved.scene.stem().string() + "/frame_####.png";
        if (args.window && (args.contact_sheet || args.animation || args.video || args.compare))
            throw std::runtime_error(
                "--window renders part of the frames: --contact-sheet, --animation, --video and "
                "--compare need them all (join the windows' frames with --resume and those "
                "outputs)");
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
        std::vector<std::filesystem::path> inputs = scene.inputs;
        inputs.insert(inputs.end(), resolved.ini_files.begin(), resolved.ini_files.end());
        check_outputs(args, pattern, selected, scene.animation, inputs);
        const std::size_t frame_pixels =
            std::size_t(scene.animation.width) * std::size_t(scene.animation.height);
        // Each frame's record of what made it, written beside it
        // (app/frame_record.hpp); --resume keeps only frames whose record
        // matches.
        FrameRecords records(render_settings(sampling, args, scene.animation, resolved.options),
                             scene.animation, resolved.scene);
        const FrameRecords::ReadFiles scene_read = records.hash_inputs(scene.inputs);
        if (args.resume) {
            ResumeCheck check = resume_check(args, pattern, selected, scene.animation, records,
                                             reading.frame_by_frame() ? nullptr : &scene_read, err);
            if (args.error_estimate && check.missing.size() < selected.size())
                err << "note: --resume: the frames kept print no estimate (the run that made "
                       "them did)\n";
            out << "--resume: " << selected.size() - check.missing.size() << " of "
                << selected.size() << " frames already written\n";
            written.assign(selected.begin(), selected.end());
            std::erase_if(written, [&](int frame) {
                return std::binary_search(check.missing.begin(), check.missing.end(), frame);
            });
            if (check.missing.empty() && !args.contact_sheet && !args.animation && !args.video)
                return 0;
            selected = check.missing;
        }
        // Each mode's render of the selected frames; a scene read frame by
        // frame renders each frame from its own reading.
        // --video: each frame added as it finishes, those already on disk
        // (--resume) read back one at a time in their turn, so the video
        // holds every frame in order and memory holds one of them, however
        // long the animation (the contact sheet and GIF keep them all).
        std::optional<tracer::VideoFile> video;
        std::size_t next_on_disk = 0;  // (of `written`)
        const auto named_video = [&](const std::function<void()>& step) {
            try {
                step();
            } catch (const std::runtime_error& e) {
                throw std::runtime_error(std::string("--video ") + e.what());
            }
        };
        const auto add_on_disk_before = [&](long long frame) {
            for (; next_on_disk < written.size() && written[next_on_disk] < frame; ++next_on_disk)
                named_video([&] {
                    video->add(tracer::read_image(
                        tracer::frame_path(pattern, written[next_on_disk]), frame_pixels));
                });
        };
        FrameSink to_video;
        if (args.video) {
            named_video([&] {
                video.emplace(*args.video, scene.animation.width, scene.animation.height, args.fps);
            });
            to_video = [&](int frame, const tracer::Image& image) {
                add_on_disk_before(frame);
                named_video([&] { video->add(image); });
            };
        }
        // Each frame written gets its record, made of the files its reading
        // read (read frame by frame: that frame's own), then goes to the
        // video.
        const FrameRecords::ReadFiles* read_now = &scene_read;
        const FrameSink recorded = [&](int frame, const tracer::Image& image) {
            records.write(frame, tracer::frame_path(pattern, frame), *read_now);
            if (to_video) to_video(frame, image);
        };
        const auto render = [&](tracer::Mode mode, bool write, std::vector<tracer::Image>* keep,
                                bool last_use, const FrameSink& sink) {
            if (!reading.frame_by_frame())
                return render_mode(scene, args, sampling, mode, pattern, selected, write, keep,
                                   last_use, err, {}, sink);
            ModeRun all;
            for (std::size_t i = 0; i < selected.size(); ++i) {
                runtime::SceneDescription alone = reading.read_frame(selected[i]);
                alone.animation = scene.animation;  // (apply_scene_defaults's shutter)
                const FrameRecords::ReadFiles frame_read = records.hash_inputs(alone.inputs);
                read_now = &frame_read;
                ModeRun run = render_mode(alone, args, sampling, mode, pattern, {selected[i]},
                                          write, keep, true, err, {i, selected.size()}, sink);
                all.counters += run.counters;
                all.frames.insert(all.frames.end(), run.frames.begin(), run.frames.end());
                read_now = &scene_read;  // (`frame_read` is gone)
            }
            return all;
        };
        const bool keep_frames = args.contact_sheet || args.animation;
        std::vector<tracer::Image> frames;
        std::vector<std::pair<std::string, ModeRun>> columns;
        const tracer::Mode mode =
            args.compare ? tracer::Mode::Spacetime : tracer::parse_mode(args.mode);
        if (!selected.empty())
            columns.emplace_back(
                tracer::mode_name(mode),
                render(mode, true, keep_frames ? &frames : nullptr, !args.compare, recorded));
        if (keep_frames && !written.empty()) {
            // (--resume) The frames on disk join those just rendered, in
            // order, read back as written (an 8-bit sRGB frame gives its
            // very bytes again).
            std::vector<std::pair<int, tracer::Image>> all;
            for (std::size_t i = 0; i < selected.size(); ++i)
                all.emplace_back(selected[i], std::move(frames[i]));
            for (const int frame : written)
                all.emplace_back(
                    frame, tracer::read_image(tracer::frame_path(pattern, frame), frame_pixels));
            std::sort(all.begin(), all.end(),
                      [](const auto& a, const auto& b) { return a.first < b.first; });
            frames.clear();
            for (auto& [frame, image] : all) frames.push_back(std::move(image));
        }
        if (args.compare)  // the paper's order: frame by frame, then spacetime
            columns.emplace(columns.begin(), "frames",
                            render(tracer::Mode::Frames, false, nullptr, true, {}));
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
            tracer::write_animation(frames, *args.animation, args.fps);
            out << "animation: " << *args.animation << "\n";
        }
        if (video) {
            add_on_disk_before(std::numeric_limits<long long>::max());
            named_video([&] { video->finish(); });
            out << "video: " << *args.video << " (" << video->frames() << " frames at " << args.fps
                << " per second)\n";
        }
        const bool print = args.stats || args.compare || (args.stats_full && !args.stats_json);
        if (print && !columns.empty()) {
            std::vector<std::pair<std::string, Counters>> counters;
            for (const auto& [name, run] : columns) counters.emplace_back(name, run.counters);
            print_stats(out, counters);
        }
        if (args.stats_json) write_stats_json(*args.stats_json, columns);
        return 0;
    });
}

}  // namespace hexant::app
