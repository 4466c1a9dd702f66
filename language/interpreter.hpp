// The scene language's entry points: read a POV-Ray-style scene, run its
// directives as it is read, and return the runtime records it describes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "language/limits.hpp"
#include "language/scene_error.hpp"
#include "runtime/scene/scene.hpp"

namespace hexant::language {

struct ParseOptions {
    runtime::Animation animation;  // image size and the clock mapping
    // Searched after the scene's own folder, in order (POV-Ray's +L).
    std::vector<std::filesystem::path> include_paths;
    // Folders #include may also read from (POV-Ray's Read_Paths), beside the
    // scene's folder, the include paths and the include folders of hexant
    // and POV-Ray.
    std::vector<std::filesystem::path> read_paths;
    // Where #fopen may write (language/file_io.hpp): the scene's output
    // folder (the folder of its images; a relative name is made there) and
    // the --allow-write folders. Empty: a scene may not write at all (text
    // read from memory, the fuzzer).
    std::filesystem::path output_folder;
    std::vector<std::filesystem::path> write_paths;
    // NAME=VALUE pairs (POV-Ray's Declare=); VALUE is a number, a vector of
    // numbers or a string, never scene text.
    std::vector<std::pair<std::string, std::string>> declares;
    // The language version the scene starts with, as if it began with
    // #version (POV-Ray's Version=, +MV); none: 3.7, with no #version read.
    std::optional<double> language_version;
    // Where #debug and #warning text goes (stderr when null).
    std::ostream* messages = nullptr;
    // Stated limits that stop runaway scenes with a clear error.
    Limits limits;
    // Every warning an error at its place (--strict): a scene that uses
    // what hexant does not render as POV-Ray does is refused.
    bool strict = false;
    // Read for one frame of the animation alone (a scene read frame by
    // frame, app/scene_reading.hpp): frame_number is that frame's number, a
    // constant, and the time read for is the frame's exposure
    // (Animation::frame_window), or with at_clock the frame's clock alone,
    // clock a constant there, as POV-Ray reads a frame (nothing in it
    // moves).
    struct FrameAlone {
        int frame = 1;
        bool at_clock = false;
    };
    std::optional<FrameAlone> frame_alone;
    // Warnings said already (by another frame's reading): not said again;
    // each new one is added. Null: every warning is said.
    std::set<std::string>* warnings_said = nullptr;
    // What a long reading has done so far (issue 45: a mesh of 10^7
    // triangles from a #for loop read for a minute without a word).
    struct Progress {
        double seconds = 0.0;         // since the reading began
        std::uint64_t steps = 0;      // loop iterations and macro calls
        std::uint64_t objects = 0;    // made for the scene (Limits::objects)
        std::uint64_t triangles = 0;  // read into meshes
    };
    // Called about once a second once the reading has run progress_delay
    // seconds (null: never), on the reading's thread.
    std::function<void(const Progress&)> progress;
    double progress_delay = 2.0;
};

// Throws SceneError for any problem in the scene (its
// may_read_frame_by_frame() when the reading stopped at what hexant cannot
// make piecewise in time, under a branch on clock).
runtime::SceneDescription parse_scene_file(const std::filesystem::path& path,
                                           const ParseOptions& options);
// The same for text in memory; `name` is used in error messages and the
// current folder is the include folder.
runtime::SceneDescription parse_scene_text(const std::string& text, const std::string& name,
                                           const ParseOptions& options);

// The folder of the include files that ship with hexant (colors.inc),
// searched after -L and before POV-Ray's own: an installed hexant's
// share/hexant/include beside its bin/, else the source tree's
// language/include (language/bundled_include_dir.cpp).
std::filesystem::path bundled_include_dir();

}  // namespace hexant::language
