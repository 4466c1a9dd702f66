#include "language/ini_file.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>
#include <stdexcept>

#include "language/povray_options.hpp"
#include "language/source_files.hpp"

namespace hexant::language {

namespace {

namespace fs = std::filesystem;

std::string unquote(const std::string& s) {
    if (s.size() >= 2 && s.front() == '"' && s.back() == '"') return s.substr(1, s.size() - 2);
    return s;
}

// Words separated by blanks; a double-quoted part may hold blanks.
std::vector<std::string> words(const std::string& line) {
    std::vector<std::string> out;
    std::string word;
    bool quoted = false;
    for (char c : line) {
        if (c == '"') {
            quoted = !quoted;
            continue;
        }
        if (!quoted && std::isspace(static_cast<unsigned char>(c))) {
            if (!word.empty()) out.push_back(std::move(word));
            word.clear();
        } else {
            word += c;
        }
    }
    if (!word.empty()) out.push_back(std::move(word));
    return out;
}

class Reader {
  public:
    Reader(IniSettings& settings, const std::string& name, const fs::path& folder)
        : s_(settings), name_(name), folder_(folder) {}

    void line(int number, const std::string& text) {
        const std::string here = place(number);
        if (text[0] == '+' || text[0] == '-') {
            for (const auto& word : words(text))
                if (!apply_povray_switch(word, here, folder_, s_))
                    s_.warnings.push_back(here + ": '" + word +
                                          "' is not a POV-Ray 3.7 switch; it is ignored");
            return;
        }
        const auto eq = text.find('=');
        if (eq == std::string::npos) {
            s_.warnings.push_back(here + ": line '" + text + "' is ignored");
            return;
        }
        const std::string written = trim_blanks(text.substr(0, eq));
        if (!apply_povray_option(written, unquote(trim_blanks(text.substr(eq + 1))), here, folder_,
                                 s_))
            s_.warnings.push_back(here + ": option '" + written + "' is ignored");
    }

    std::string place(int number) const { return name_ + ":" + std::to_string(number); }

  private:
    IniSettings& s_;
    const std::string& name_;
    const fs::path& folder_;
};

}  // namespace

IniSettings parse_ini_text(const std::string& text, const std::string& name, const fs::path& folder,
                           const std::string& section) {
    IniSettings settings;
    Reader reader(settings, name, folder);
    const std::string wanted = ascii_lower(trim_blanks(section));
    bool reading = true;  // the unlabelled lines are always read
    bool found = false;
    std::istringstream in(text);
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        if (const auto c = line.find(';'); c != std::string::npos) line.erase(c);
        line = trim_blanks(line);
        if (line.empty()) continue;
        if (line[0] == '[') {
            const auto close = line.find(']');
            const std::string label = trim_blanks(
                line.substr(1, close == std::string::npos ? std::string::npos : close - 1));
            reading = !wanted.empty() && ascii_lower(label) == wanted;
            found = found || reading;
            if (!reading && wanted.empty())
                settings.warnings.push_back(reader.place(number) + ": section [" + label +
                                            "] is read only when selected, as " + name + "[" +
                                            label + "]");
            continue;
        }
        if (reading) reader.line(number, line);
    }
    if (!wanted.empty() && !found)
        throw std::runtime_error(name + ": has no section [" + section + "]");
    return settings;
}

IniSettings read_ini_file(const fs::path& path, const std::string& section) {
    // A regular file of sane size only: a FIFO named as the .ini blocked
    // the run forever, /dev/zero would fill the memory.
    constexpr std::size_t kMostIniBytes = std::size_t(16) << 20;
    std::string text;
    try {
        text = read_source_text(path, kMostIniBytes);
    } catch (const std::runtime_error& e) {
        throw std::runtime_error("cannot read " + path.string() + ": " + e.what());
    }
    return parse_ini_text(text, path.string(), path.parent_path(), section);
}

std::optional<IniReference> ini_reference(const std::string& argument) {
    IniReference reference{argument, {}};
    std::string file = argument;
    if (!argument.empty() && argument.back() == ']') {
        const auto open = argument.rfind('[');
        if (open == std::string::npos) return std::nullopt;
        file = argument.substr(0, open);
        reference.section = argument.substr(open + 1, argument.size() - open - 2);
    }
    const std::string tail = ascii_lower(file.size() >= 4 ? file.substr(file.size() - 4) : file);
    if (file.size() <= 4 || tail != ".ini") return std::nullopt;
    reference.file = file;
    return reference;
}

void apply_ini_settings(const IniSettings& s, ParseOptions& options, fs::path& scene) {
    auto& a = options.animation;
    if (s.input_file) scene = *s.input_file;
    if (s.width) a.width = *s.width;
    if (s.height) a.height = *s.height;
    if (s.initial_frame) a.initial_frame = *s.initial_frame;
    if (s.final_frame) a.final_frame = *s.final_frame;
    if (s.initial_clock) a.initial_clock = *s.initial_clock;
    if (s.final_clock) a.final_clock = *s.final_clock;
    if (s.cyclic) a.cyclic = *s.cyclic;
    options.include_paths.insert(options.include_paths.end(), s.library_paths.begin(),
                                 s.library_paths.end());
    options.declares.insert(options.declares.end(), s.declares.begin(), s.declares.end());
    if (s.version) options.language_version = s.version->value;
}

}  // namespace hexant::language
