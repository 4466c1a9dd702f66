#include "language/ini_file.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "language/source_files.hpp"

namespace hexant::language {

namespace {

namespace fs = std::filesystem;

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r\f\v");
    if (b == std::string::npos) return {};
    const auto e = s.find_last_not_of(" \t\r\f\v");
    return s.substr(b, e - b + 1);
}

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

// The options hexant reads, by their lower-case .ini key.
enum class Option {
    InputFile,
    Width,
    Height,
    InitialFrame,
    FinalFrame,
    InitialClock,
    FinalClock,
    Cyclic,
    LibraryPath,
    Declare,
    Unknown,
};

Option option_of_key(const std::string& key) {
    static const std::pair<const char*, Option> keys[] = {
        {"input_file_name", Option::InputFile},
        {"width", Option::Width},
        {"height", Option::Height},
        {"initial_frame", Option::InitialFrame},
        {"final_frame", Option::FinalFrame},
        {"initial_clock", Option::InitialClock},
        {"final_clock", Option::FinalClock},
        {"cyclic_animation", Option::Cyclic},
        {"library_path", Option::LibraryPath},
        {"declare", Option::Declare},
    };
    for (const auto& [name, option] : keys)
        if (key == name) return option;
    return Option::Unknown;
}

class Reader {
  public:
    Reader(IniSettings& settings, const std::string& name, const fs::path& folder)
        : s_(settings), name_(name), folder_(folder) {}

    void line(int number, const std::string& text) {
        place_ = name_ + ":" + std::to_string(number);
        if (text[0] == '+' || text[0] == '-') {
            for (const auto& word : words(text)) switch_word(word);
            return;
        }
        const auto eq = text.find('=');
        if (eq == std::string::npos) {
            s_.warnings.push_back(place_ + ": line '" + text + "' is ignored");
            return;
        }
        const std::string written = trim(text.substr(0, eq));
        set(option_of_key(lower(written)), written, unquote(trim(text.substr(eq + 1))));
    }

    std::string place(int number) const { return name_ + ":" + std::to_string(number); }

  private:
    // One switch such as +W320, +KFF64, -KC or +Llib.
    void switch_word(const std::string& word) {
        if (word.size() < 2 || (word[0] != '+' && word[0] != '-')) {
            s_.warnings.push_back(place_ + ": '" + word + "' is not a switch; it is ignored");
            return;
        }
        const bool on = word[0] == '+';
        const std::string body = word.substr(1);
        const std::string upper_body = [&] {
            std::string u = body;
            std::transform(u.begin(), u.end(), u.begin(),
                           [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
            return u;
        }();
        auto starts = [&](const char* prefix) { return upper_body.rfind(prefix, 0) == 0; };
        // A number follows +W and +H; +WT4 or +HT... are other switches.
        auto numeric_after = [&](std::size_t n) {
            return body.size() > n && (std::isdigit(static_cast<unsigned char>(body[n])) ||
                                       body[n] == '.' || body[n] == '+' || body[n] == '-');
        };
        if (upper_body == "KC") {
            s_.cyclic = on;
        } else if (starts("KFI")) {
            set(Option::InitialFrame, word, body.substr(3));
        } else if (starts("KFF")) {
            set(Option::FinalFrame, word, body.substr(3));
        } else if (starts("KI")) {
            set(Option::InitialClock, word, body.substr(2));
        } else if (starts("KF") && numeric_after(2)) {
            set(Option::FinalClock, word, body.substr(2));
        } else if (starts("W") && numeric_after(1)) {
            set(Option::Width, word, body.substr(1));
        } else if (starts("H") && numeric_after(1)) {
            set(Option::Height, word, body.substr(1));
        } else if (starts("L") && body.size() > 1) {
            set(Option::LibraryPath, word, body.substr(1));
        } else if (starts("I") && body.size() > 1) {
            set(Option::InputFile, word, body.substr(1));
        } else {
            s_.warnings.push_back(place_ + ": switch '" + word + "' is ignored");
        }
    }

    [[noreturn]] void bad(const std::string& written, const std::string& needs,
                          const std::string& value) const {
        throw std::runtime_error(place_ + ": " + written + " needs " + needs + ", not '" + value +
                                 "'");
    }

    int integer(const std::string& written, const std::string& value) const {
        const char* begin = value.data() + (value.rfind('+', 0) == 0 ? 1 : 0);
        const char* end = value.data() + value.size();
        int v = 0;
        const auto [stop, error] = std::from_chars(begin, end, v);
        if (value.empty() || error != std::errc() || stop != end)
            bad(written, "a whole number", value);
        return v;
    }

    double real(const std::string& written, const std::string& value) const {
        char* stop = nullptr;
        const double v = std::strtod(value.c_str(), &stop);
        if (value.empty() || stop != value.c_str() + value.size() || !std::isfinite(v) ||
            std::isspace(static_cast<unsigned char>(value[0])))
            bad(written, "a number", value);
        return v;
    }

    bool boolean(const std::string& written, const std::string& value) const {
        const std::string v = lower(value);
        if (v == "on" || v == "true" || v == "yes" || v == "1") return true;
        if (v == "off" || v == "false" || v == "no" || v == "0") return false;
        bad(written, "on or off", value);
    }

    void set(Option option, const std::string& written, const std::string& value) {
        switch (option) {
            case Option::InputFile:
                if (value.empty()) bad(written, "a file name", value);
                s_.input_file = folder_ / value;
                break;
            case Option::Width:
                s_.width = integer(written, value);
                break;
            case Option::Height:
                s_.height = integer(written, value);
                break;
            case Option::InitialFrame:
                s_.initial_frame = integer(written, value);
                break;
            case Option::FinalFrame:
                s_.final_frame = integer(written, value);
                break;
            case Option::InitialClock:
                s_.initial_clock = real(written, value);
                break;
            case Option::FinalClock:
                s_.final_clock = real(written, value);
                break;
            case Option::Cyclic:
                s_.cyclic = boolean(written, value);
                break;
            case Option::LibraryPath:
                if (value.empty()) bad(written, "a folder", value);
                s_.library_paths.push_back(folder_ / value);
                s_.library_path_places.push_back(place_);
                break;
            case Option::Declare: {
                const auto eq = value.find('=');
                const std::string name = eq == std::string::npos ? "" : trim(value.substr(0, eq));
                const std::string text = eq == std::string::npos ? "" : trim(value.substr(eq + 1));
                if (name.empty() || text.empty()) bad(written, "NAME=VALUE", value);
                s_.declares.emplace_back(name, text);
                break;
            }
            case Option::Unknown:
                s_.warnings.push_back(place_ + ": option '" + written + "' is ignored");
                break;
        }
    }

    IniSettings& s_;
    const std::string& name_;
    const fs::path& folder_;
    std::string place_;
};

}  // namespace

IniSettings parse_ini_text(const std::string& text, const std::string& name, const fs::path& folder,
                           const std::string& section) {
    IniSettings settings;
    Reader reader(settings, name, folder);
    const std::string wanted = lower(trim(section));
    bool reading = true;  // the unlabelled lines are always read
    bool found = false;
    std::istringstream in(text);
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        if (const auto c = line.find(';'); c != std::string::npos) line.erase(c);
        line = trim(line);
        if (line.empty()) continue;
        if (line[0] == '[') {
            const auto close = line.find(']');
            const std::string label =
                trim(line.substr(1, close == std::string::npos ? std::string::npos : close - 1));
            reading = !wanted.empty() && lower(label) == wanted;
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
    const std::string tail = lower(file.size() >= 4 ? file.substr(file.size() - 4) : file);
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
}

}  // namespace hexant::language
