// `hexant bench error-time`: the error of one frame against a high-sample
// reference, beside the time it took and the frame's own estimate, for each
// mode at growing sample counts; the slope of error against samples and
// against time; with --targets, adaptive sampling's time to each target
// beside uniform sampling's. Writes a CSV and a log-log plot (SVG: time
// across, error up, one curve per mode; the faster method is the lower
// curve).
#pragma once

#include <iosfwd>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "app/command_line.hpp"
#include "app/hierarchy_arguments.hpp"

namespace hexant::app {

struct ErrorTimeArguments {
    SceneArguments scene;
    std::optional<int> frame;  // default: the animation's middle frame
    std::string spp_list = "1,2,4,8,16,32,64,128,256";
    std::string modes = "spacetime,frames";
    int reference_spp = 0;                  // 0: 4 times the largest of spp_list
    std::optional<std::string> output_dir;  // default out/SCENE/error-time
    int threads = 0;
    // Each point rendered this many times, its time the median: a frame
    // of a tenth of a second is as noisy as the machine.
    int repeat = 1;
    // Adaptive sampling (--target-error) at each of these RMSE targets, with
    // the largest of spp_list as the ceiling: its true error, and the
    // samples and time uniform sampling needs for that error (empty: none).
    std::string targets;
    HierarchyArguments hierarchy;
};

void add_error_time_arguments(CLI::App& command, ErrorTimeArguments& arguments);

// Returns the exit status; errors go to `err` naming their place.
int run_error_time(const ErrorTimeArguments& arguments, std::ostream& out, std::ostream& err);

}  // namespace hexant::app
