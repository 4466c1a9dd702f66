// The shape every subcommand shares:
//   hexant SUBCOMMAND SCENE.pov [FILE.ini ...] [POV-Ray switches] [flags]
// POV-Ray .ini files, switches (+W640, -D) and Key=Value options apply in
// the order written, as in POV-Ray; then hexant's flags override them.
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
    // The scene, .ini files, POV-Ray switches and Key=Value options, in
    // order (a switch beginning with - marked: app/povray_words.hpp).
    std::vector<std::string> files;
    std::optional<int> width, height, frame_count;
    std::optional<std::string> clock_range;  // A:B
    bool cyclic = false;
    std::optional<double> shutter;
    std::optional<std::string> shutter_curve;  // runtime::ShutterCurve::parse
    std::optional<double> rolling_shutter;
    std::optional<std::string> shutter_position;  // start, centre (center) or end
    bool shutter_beyond_range = false;
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
    std::optional<double> at_clock;                // --clock C, or POV-Ray's +K
    std::vector<std::filesystem::path> ini_files;  // read, canonical (inputs too)
    // Every POV-Ray option the .ini files and switches set, the last of
    // each (what `render` maps onto its flags: app/povray_render_options).
    language::PovRaySettings povray;
};

// Applies the words in order: an .ini file (a word ending in .ini, or
// .ini[Label] to select a section), a POV-Ray switch (+W640, or a marked
// -D), a POV-Ray `Key=Value` option, or else the scene; then the flags.
// A scene named as a word wins over an .ini's Input_File_Name; one named
// both as a word and by +I or Input_File_Name= on the command line is an
// error. Throws std::runtime_error naming the file and line of a bad .ini
// setting, the switch of a bad or unknown switch, or a bad flag.
ResolvedScene resolve(const SceneArguments& arguments);

// Runs a subcommand's body; a scene error is printed with its place and
// context, any other error as "hexant: error: ...", and either returns 1.
int run_reporting_errors(std::ostream& err, const std::function<int()>& body);

}  // namespace hexant::app
