// POV-Ray .ini files: the options hexant reads from them.
//
// `Key=Value` lines (keys in any case), `;` comments, and POV-Ray's switches
// (`+W320 +H240`, several on a line). As in POV-Ray 3.7, the lines before the
// first `[Label]` are always read, and a labelled section only when it is
// selected as `FILE.ini[Label]`. The options read: Input_File_Name (+I),
// Width (+W), Height (+H), Initial_Frame (+KFI), Final_Frame (+KFF),
// Initial_Clock (+KI), Final_Clock (+KF), Cyclic_Animation (+KC/-KC),
// Library_Path (+L) and Declare=NAME=VALUE. Other options are POV-Ray's
// rendering options: each is ignored with a warning.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "language/interpreter.hpp"

namespace hexant::language {

// What one .ini file sets; an option it does not mention stays empty.
struct IniSettings {
    // Relative paths are taken from the .ini file's folder.
    std::optional<std::filesystem::path> input_file;
    std::optional<int> width, height;
    std::optional<int> initial_frame, final_frame;
    std::optional<double> initial_clock, final_clock;
    std::optional<bool> cyclic;
    std::vector<std::filesystem::path> library_paths;           // in order; they accumulate
    std::vector<std::string> library_path_places;               // "FILE:LINE" of each
    std::vector<std::pair<std::string, std::string>> declares;  // NAME, VALUE
    std::vector<std::string> warnings;  // "FILE:LINE: ..." for ignored lines
};

// Reads the text of an .ini file. `name` names it in messages; `folder`
// resolves relative paths; `section` is the label selected (empty: only the
// unlabelled lines). Throws std::runtime_error naming `name:LINE` for a bad
// value, and for a selected section the file lacks.
IniSettings parse_ini_text(const std::string& text, const std::string& name,
                           const std::filesystem::path& folder, const std::string& section = {});

// The same for a file on disk; throws std::runtime_error if it cannot be read.
IniSettings read_ini_file(const std::filesystem::path& path, const std::string& section = {});

// A command-line word that names an .ini file: `res.ini` or `res.ini[High]`.
struct IniReference {
    std::filesystem::path file;
    std::string section;  // empty when none is selected
};
// The file and section `argument` names, or nothing if it is not an .ini file
// (its name does not end in .ini, in any case, before an optional [Label]).
std::optional<IniReference> ini_reference(const std::string& argument);

// Applies the settings onto `options` and `scene`: each option the file set
// replaces the current value; library paths and declarations append.
void apply_ini_settings(const IniSettings& settings, ParseOptions& options,
                        std::filesystem::path& scene);

}  // namespace hexant::language
