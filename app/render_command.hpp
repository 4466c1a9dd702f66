// `hexant render`: frames of an animation, their contact sheet and animated
// file, and the paper's table rows (--stats, --compare).
#pragma once

#include <iosfwd>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "app/command_line.hpp"
#include "app/hierarchy_arguments.hpp"

namespace hexant::app {

struct RenderArguments {
    SceneArguments scene;
    std::string mode = "spacetime";
    std::optional<int> samples_per_pixel;  // default: the scene's (MegaPOV's motion_blur), else 1
    bool no_jitter = false;
    unsigned seed = 0;
    std::optional<std::string> frames;  // A:B
    std::optional<std::string> output;  // pattern with ####
    std::optional<std::string> contact_sheet, animation, stats_json;
    bool stats = false;
    bool compare = false;
    int threads = 0;
    // Each frame's error estimated from two independent halves of its
    // samples (tracer/frame_estimate.hpp), printed; --error-image writes
    // each frame's per-pixel estimate (a pattern with ####, as --output).
    bool error_estimate = false;
    std::optional<std::string> error_image;
    HierarchyArguments hierarchy;
};

void add_render_arguments(CLI::App& command, RenderArguments& arguments);

// Renders as the arguments say; returns the exit status. Errors go to `err`
// naming their place; frames finished before an error stay written.
int run_render(const RenderArguments& arguments, std::ostream& out, std::ostream& err);

}  // namespace hexant::app
