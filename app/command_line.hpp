// The shape every subcommand shares:
//   hexant SUBCOMMAND SCENE.pov [FILE.ini ...] [flags]
// POV-Ray .ini files apply in order, then flags override them.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "language/ini_file.hpp"
#include "language/interpreter.hpp"

namespace hexant::app {

// What the command line says, before it is resolved into ParseOptions.
struct SceneArguments {
    std::vector<std::string> files;  // the scene and .ini files, in order
    std::optional<int> width, height, frame_count;
    std::optional<std::string> clock_range;  // A:B
    bool cyclic = false;
    std::optional<double> shutter;
    std::optional<std::string> shutter_curve;  // runtime::ShutterCurve::parse
    std::optional<double> rolling_shutter;
    std::vector<std::string> include_paths;
    std::vector<std::string> read_paths;
    std::vector<std::string> write_paths;
    std::vector<std::string> declares;  // NAME=VALUE
    bool strict = false;                // every warning an error
    // Limits (language/limits.hpp); each raises or lowers one default.
    std::optional<std::size_t> max_loop_iterations, max_iterations, max_time_pieces, max_text_read,
        max_string_length, max_array_memory_mib, max_debug_output;
    std::optional<int> max_macro_depth, max_include_depth;
    std::optional<long long> max_frames, max_pixels;
    std::optional<std::uint64_t> max_objects, max_triangles;
};

// Adds the shared positionals and flags to a subcommand.
void add_scene_arguments(CLI::App& command, SceneArguments& arguments);

struct ResolvedScene {
    std::filesystem::path scene;
    language::ParseOptions options;
    std::vector<std::string> warnings;             // from .ini files
    std::optional<double> at_clock;                // --clock C
    std::vector<std::filesystem::path> ini_files;  // read, canonical (inputs too)
};

// Applies the .ini files in order (a word ending in .ini, or .ini[Label] to
// select a section, is an .ini file; any other is the scene), then the flags.
// Throws std::runtime_error naming the file and line of a bad .ini setting,
// or a bad flag.
ResolvedScene resolve(const SceneArguments& arguments);

// Runs a subcommand's body; a scene error is printed with its place and
// context, any other error as "hexant: error: ...", and either returns 1.
int run_reporting_errors(std::ostream& err, const std::function<int()>& body);

}  // namespace hexant::app
