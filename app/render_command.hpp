// `hexant render`: frames of an animation, their contact sheet, animated
// GIF and video, and the paper's table rows (--stats, --compare).
#pragma once

#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "app/command_line.hpp"
#include "app/hierarchy_arguments.hpp"
#include "runtime/scene/scene.hpp"

namespace hexant::app {

struct RenderArguments {
    SceneArguments scene;
    std::string mode = "spacetime";
    // Default: the scene's (MegaPOV's motion_blur); else, with jitter,
    // adaptive sampling to kDefaultTargetError under kDefaultCeiling; else 1.
    std::optional<int> samples_per_pixel;
    bool no_jitter = false;
    unsigned seed = 0;
    std::optional<std::string> frames;  // A:B
    // I/N: the I-th (0 to N-1, as Slurm numbers an array's tasks) of N
    // consecutive windows of the frames, each its own hierarchy over its own
    // time (window_frames).
    std::optional<std::string> window;
    // --resume: frames already written by this very render (their records
    // match it: app/frame_record.hpp) are kept, others rendered again, a
    // killed run's temporaries removed. With resume_keep (--resume=keep,
    // POV-Ray's +C as POV-Ray does it) any readable frame of the right
    // size is kept, however it was made.
    bool resume = false;
    bool resume_keep = false;
    std::string resume_text;            // (the flag's own storage: check or keep)
    std::optional<std::string> output;  // pattern with ####
    // How the frames' format is written, when not the extension's own way:
    // "rle" (Targa, POV-Ray's +FC) or "16" (PNG, +FN16); image_format_for.
    std::string output_variant;
    std::optional<std::string> contact_sheet, animation, stats_json;
    // --video: .mp4 (H.264) or .webm (VP9), fed each frame as it finishes
    // (tracer/video_file.hpp); --fps the frame rate of it and the GIF.
    std::optional<std::string> video;
    double fps = 24.0;
    bool stats = false;
    bool stats_full = false;  // --stats-full: count a full build's cells too
    bool compare = false;
    std::optional<int> threads;  // none: all cores
    // The speed of light (tracer/light_travel.hpp), scene units per clock
    // unit: none, instant light.
    std::optional<double> light_speed;
    // --gi: radiosity's indirect light from POV-Ray's irradiance cache
    // (per frame), or sampled per sample at its own time ("path").
    bool gi_path = false;
    // Each frame's error estimate (tracer/frame_estimate.hpp) is printed
    // whenever there is one (2 or more jittered samples); --error-estimate
    // asks for it (refused without them). --error-image writes each
    // frame's per-pixel estimate (a pattern with ####, as --output).
    bool error_estimate = false;
    std::optional<std::string> error_image;
    // Adaptive sampling (RenderSettings::target_error): --spp is then the
    // ceiling. --samples-image writes the samples each pixel took.
    std::optional<double> target_error;
    std::optional<std::string> samples_image;
    HierarchyArguments hierarchy;
};

// What `render` checks before it renders anything (the frames, the
// outputs' names and formats, the flags that cannot go together), for a
// scene already read: `hexant farm` asks it of every task and the join.
// std::runtime_error naming the flag otherwise.
void check_render_plan(const RenderArguments& args, const std::filesystem::path& scene_file,
                       const runtime::SceneDescription& scene);

// Window I of N (text "I/N") of `frames`: the I-th of N runs of
// consecutive frames, as even as can be (window I holds frames
// floor(I K / N) to floor((I + 1) K / N) - 1 of the K, sizes differing by
// at most one); empty when there are more windows than frames.
// std::runtime_error naming --window for a malformed or out-of-range one.
std::vector<int> window_frames(const std::string& text, const std::vector<int>& frames);

// The default target: an RMSE of 1/128 in linear light per frame, about
// 1.3 steps of an 8-bit sRGB file at mid-grey (0.5 linear) and 2 at a
// fifth. atom's electron streaks render smooth with it at a mean of 5.3
// samples per pixel, 2.9 s for its 64 frames on 2 cores (docs/benchmarks.md,
// "Issue 47").
inline constexpr double kDefaultTargetError = 1.0 / 128.0;
inline constexpr int kDefaultCeiling = 256;

// How a render samples: per pixel `samples` (with a target, the ceiling).
struct Sampling {
    int samples = 1;
    double target_error = 0.0;  // 0: uniform
};
// From the arguments and the scene; std::runtime_error naming the flags
// when they do not go together.
Sampling resolve_sampling(const RenderArguments& arguments, const runtime::SceneDescription& scene);
// --target-error's text: a positive finite number or a fraction A/B;
// CLI::ValidationError otherwise.
double parse_target_error(const std::string& text);

void add_render_arguments(CLI::App& command, RenderArguments& arguments);

// Renders as the arguments say; returns the exit status. Errors go to `err`
// naming their place; frames finished before an error stay written.
int run_render(const RenderArguments& arguments, std::ostream& out, std::ostream& err);

}  // namespace hexant::app
