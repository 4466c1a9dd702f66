// hexant: renders animations written in a POV-Ray-style scene language with
// Glassner's spacetime ray tracing. Each subcommand takes
//   hexant SUBCOMMAND SCENE.pov [FILE.ini ...] [POV-Ray switches] [flags]
// and `hexant SCENE.pov|SCENE.ini [...]` alone is `hexant render ...`, as
// `povray` is called (app/povray_words.hpp).
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <malloc.h>

#include "app/command_line.hpp"
#include "app/error_time_command.hpp"
#include "app/farm_command.hpp"
#include "app/man_page.hpp"
#include "app/merge_stats.hpp"
#include "app/povray_render_options.hpp"
#include "app/povray_words.hpp"
#include "app/render_command.hpp"
#include "app/scene_dump.hpp"
#include "app/scene_reading.hpp"
#include "app/scene_summary.hpp"
#include "app/version.hpp"
#include "language/interpreter.hpp"
#include "tracer/whole_file.hpp"

int main(int argc, char** argv) {
    using namespace hexant;
    // An interrupted run leaves no half-written file behind.
    tracer::install_cleanup_on_signals();
    // Buffers of a megabyte or more (a large cell's build, an image) are
    // mapped from the system and returned when freed. glibc's threshold
    // otherwise rises to the largest buffer freed, after which such
    // buffers stay in the heap: at swarm 10^5 the peak held a leaf build's
    // 12.8 MB that was already freed (docs/benchmarks.md, "Scale: the swarm").
    mallopt(M_MMAP_THRESHOLD, 1 << 20);
    CLI::App program{"hexant: spacetime ray tracing of POV-Ray-style animated scenes"};
    program.require_subcommand(1);
    program.set_version_flag("--version", app::version_text());

    app::SceneArguments check_arguments;
    CLI::App* check = program.add_subcommand(
        "check", "Read and evaluate a scene; summarize it, or report the first error");
    app::add_scene_arguments(*check, check_arguments);

    app::SceneArguments dump_arguments;
    CLI::App* dump =
        program.add_subcommand("dump", "Print every object with its parameters at one clock value");
    app::add_scene_arguments(*dump, dump_arguments);

    app::RenderArguments render_arguments;
    CLI::App* render = program.add_subcommand(
        "render", "Render the animation's frames with spacetime ray tracing");
    app::add_render_arguments(*render, render_arguments);

    CLI::App* farm = program.add_subcommand(
        "farm",
        "Write (and with --submit, submit) a Slurm job array that renders the animation as "
        "--windows N "
        "time windows, and a join job for the contact sheet, animation and video: hexant farm "
        "SCENE.pov "
        "[INI ...] [render flags] --windows N [--partition P] [--time T] [--farm-dir DIR] "
        "[--submit]");
    farm->prefix_command();
    farm->allow_extras();
    farm->footer(
        "Farm flags (the rest goes to every task's `render` as written):\n"
        "  --windows N          the windows, one Slurm array task each (at most the frames)\n"
        "  --partition P        #SBATCH --partition for the array and the join\n"
        "  --time T             #SBATCH --time (Slurm's format, e.g. 01:00:00)\n"
        "  --farm-dir DIR       where the scripts, logs and statistics go (default "
        "out/SCENE/farm)\n"
        "  --contact-sheet F    the join's contact sheet of every frame\n"
        "  --animation F.gif    the join's animated GIF of every frame\n"
        "  --video F.mp4|F.webm the join's video of every frame (read back from disk)\n"
        "  --submit             run submit.sh (sbatch) and print the job ids; else print the "
        "command\n"
        "Each task runs render ... --window I/N --resume --stats-json DIR/window_I.json; the join, "
        "after\n"
        "every task succeeded, runs render ... --resume with the sheet, GIF and video, then "
        "merge-stats.");

    std::vector<std::string> merge_inputs;
    std::string merge_output;
    CLI::App* merge = program.add_subcommand(
        "merge-stats",
        "The statistics of windows (render --window I/N --stats-json) as one run's: counts and "
        "times summed, memory the largest, the ratios from the sums, and each window's build and "
        "render times listed. A window resumed counts only the frames it rendered");
    merge->add_option("windows", merge_inputs, "The windows' statistics files, in window order")
        ->required();
    merge->add_option("-o,--output", merge_output, "The merged statistics (JSON)")->required();

    CLI::App* bench = program.add_subcommand("bench", "Measure hexant: speed and error");
    bench->require_subcommand(1);
    app::ErrorTimeArguments error_time_arguments;
    CLI::App* error_time = bench->add_subcommand(
        "error-time",
        "Error of one frame against a high-sample reference, against its run time, "
        "per mode and sample count (CSV and log-log plot)");
    app::add_error_time_arguments(*error_time, error_time_arguments);

    // Hidden (no group): the build writes hexant.1 with it (app/man_page.hpp).
    CLI::App* man_page =
        program.add_subcommand("man-page", "Print the manual page (roff)")->group("");

    // (CLI11_PARSE, over the words as POV-Ray's switches need them.)
    program.name(argc > 0 ? argv[0] : "hexant");
    std::vector<std::string> words = app::command_line_words(argc, argv);
    std::reverse(words.begin(), words.end());
    try {
        program.parse(words);
    } catch (const CLI::ParseError& e) {
        return program.exit(e);
    }
    if (man_page->parsed()) {
        app::write_man_page(program, std::cout);
        return std::cout.flush() ? 0 : 1;  // a full disk is no page
    }
    if (render->parsed()) return app::run_render(render_arguments, std::cout, std::cerr);
    if (merge->parsed())
        return app::run_merge_stats(merge_inputs, merge_output, std::cout, std::cerr);
    if (farm->parsed())
        return app::run_reporting_errors(std::cerr, [&] {
            app::FarmArguments arguments = app::split_farm_arguments(farm->remaining());
            arguments.hexant = std::filesystem::canonical("/proc/self/exe").string();
            return app::run_farm(arguments, std::cout, std::cerr);
        });
    if (error_time->parsed())
        return app::run_error_time(error_time_arguments, std::cout, std::cerr);

    const app::SceneArguments& arguments = check->parsed() ? check_arguments : dump_arguments;
    return app::run_reporting_errors(std::cerr, [&] {
        app::ResolvedScene resolved = app::resolve(arguments);
        for (const auto& warning : resolved.warnings) std::cerr << warning << "\n";
        app::note_render_only(resolved, check->parsed() ? "check" : "dump", std::cerr);
        app::SceneReading reading(resolved, std::cerr);
        const runtime::SceneDescription& scene = reading.scene();
        const runtime::Animation& animation = scene.animation;
        if (check->parsed()) {
            app::summarize_scene(scene, std::cout);
            if (reading.frame_by_frame()) {
                // Every frame is read, so that one that cannot be shows now.
                for (int frame = animation.initial_frame; frame <= animation.final_frame; ++frame)
                    (void)reading.read_frame(frame);
                std::cout << "read frame by frame: " << animation.frame_count()
                          << " frames, each read alone (above: the first)\n";
            }
        } else {
            const double clock = resolved.at_clock.value_or(animation.time_begin());
            if (!reading.frame_by_frame()) {
                app::dump_scene(scene, clock, std::cout);
            } else {
                // The frame whose shutter holds the clock, read alone.
                int frame = animation.initial_frame;
                while (frame < animation.final_frame &&
                       (animation.clock_delta() > 0.0 ? animation.frame_start(frame + 1) <= clock
                                                      : animation.frame_start(frame + 1) >= clock))
                    ++frame;
                app::dump_scene(reading.read_frame(frame), clock, std::cout);
            }
        }
        return 0;
    });
}
