// POV-Ray .ini files: their lines and sections.
//
// `Key=Value` lines (keys in any case), `;` comments, and POV-Ray's switches
// (`+W320 +H240`, several on a line). As in POV-Ray 3.7, the lines before the
// first `[Label]` are always read, and a labelled section only when it is
// selected as `FILE.ini[Label]`. Each option and switch means what it means
// on the command line (language/povray_options.hpp, one table for both);
// one hexant has no use for, or a line that is none, is ignored with a
// warning.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "language/interpreter.hpp"
#include "language/povray_options.hpp"

namespace hexant::language {

// What one .ini file sets (POV-Ray's options, whatever set them).
using IniSettings = PovRaySettings;

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

// Applies the settings that reading a scene uses onto `options` and
// `scene`: each option set replaces the current value (Version the
// language's at the start, as POV-Ray's +MV); library paths and
// declarations append. (Clock and the render's options are the command
// line's to apply: app/command_line.hpp.)
void apply_ini_settings(const IniSettings& settings, ParseOptions& options,
                        std::filesystem::path& scene);

}  // namespace hexant::language
