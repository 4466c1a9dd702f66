#include "app/command_line.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <stdexcept>

namespace hexant::app {

void add_scene_arguments(CLI::App& command, SceneArguments& a) {
    command.add_option("files", a.files, "The scene (.pov) and POV-Ray .ini files, in order")
        ->required();
    command.add_option("-W,--width", a.width, "Image width in pixels (default 320)");
    command.add_option("-H,--height", a.height, "Image height in pixels (default 240)");
    command.add_option("--frame-count", a.frame_count,
                       "Frames of the animation: Initial_Frame=1, Final_Frame=N");
    command.add_option("--clock", a.clock_range,
                       "A:B sets Initial_Clock and Final_Clock; a single C is POV-Ray's +K: the "
                       "clock of a still, and the instant `dump` evaluates");
    command.add_flag("--cyclic", a.cyclic, "Cyclic animation (POV-Ray's Cyclic_Animation)");
    command.add_option("--shutter", a.shutter,
                       "Fraction of each frame's clock step the shutter is open (default 1)");
    command.add_option("-L,--include-path", a.include_paths,
                       "Folder searched for #include after the scene's own (POV-Ray's +L)");
    command.add_option("--declare", a.declares, "NAME=VALUE, as POV-Ray's Declare=");
    command.add_option("--max-loop-iterations", a.max_loop_iterations,
                       "Stop a #while or #for after this many iterations (default 10^7)");
}

namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r\"");
    if (b == std::string::npos) return {};
    const auto e = s.find_last_not_of(" \t\r\"");
    return s.substr(b, e - b + 1);
}

bool is_ini(const std::string& file) { return lower(std::filesystem::path(file).extension().string()) == ".ini"; }

}  // namespace

void apply_ini_file(const std::filesystem::path& ini, ResolvedScene& r) {
    std::ifstream in(ini);
    if (!in) throw std::runtime_error("cannot read " + ini.string());
    std::string line;
    int number = 0;
    auto& a = r.options.animation;
    while (std::getline(in, line)) {
        ++number;
        const std::string place = ini.string() + ":" + std::to_string(number);
        if (auto c = line.find(';'); c != std::string::npos) line.erase(c);
        line = trim(line);
        if (line.empty() || line[0] == '[') continue;
        std::string key, value, written;  // written: the key as the file spells it
        if (line[0] == '+' || line[0] == '-') {  // a switch such as +W320 or +KFF64
            const bool on = line[0] == '+';
            const std::string s = line.substr(1);
            static const std::vector<std::pair<std::string, std::string>> switches = {
                {"KFI", "initial_frame"}, {"KFF", "final_frame"}, {"KI", "initial_clock"},
                {"KF", "final_clock"},    {"KC", "cyclic_animation"}, {"W", "width"},
                {"H", "height"},          {"L", "library_path"}};
            bool found = false;
            for (const auto& [prefix, name] : switches) {
                if (lower(s.substr(0, prefix.size())) == lower(prefix)) {
                    key = name;
                    written = line;
                    value = s.substr(prefix.size());
                    if (name == "cyclic_animation") value = on ? "on" : "off";
                    found = true;
                    break;
                }
            }
            if (!found) {
                r.warnings.push_back(place + ": switch '" + line + "' is ignored");
                continue;
            }
        } else {
            const auto eq = line.find('=');
            if (eq == std::string::npos) {
                r.warnings.push_back(place + ": line '" + line + "' is ignored");
                continue;
            }
            written = trim(line.substr(0, eq));
            key = lower(written);
            value = trim(line.substr(eq + 1));
        }
        auto integer = [&]() {
            try {
                std::size_t used = 0;
                const int v = std::stoi(value, &used);
                if (used != value.size()) throw std::invalid_argument(value);
                return v;
            } catch (const std::exception&) {
                throw std::runtime_error(place + ": " + written + " needs a whole number, not '" + value + "'");
            }
        };
        auto number_value = [&]() {
            try {
                std::size_t used = 0;
                const double v = std::stod(value, &used);
                if (used != value.size()) throw std::invalid_argument(value);
                return v;
            } catch (const std::exception&) {
                throw std::runtime_error(place + ": " + written + " needs a number, not '" + value + "'");
            }
        };
        auto boolean = [&]() {
            const std::string v = lower(value);
            if (v == "on" || v == "true" || v == "yes" || v == "1" || v.empty()) return true;
            if (v == "off" || v == "false" || v == "no" || v == "0") return false;
            throw std::runtime_error(place + ": " + written + " needs on or off, not '" + value + "'");
        };
        if (key == "input_file_name") {
            r.scene = ini.parent_path() / value;
        } else if (key == "width") {
            a.width = integer();
        } else if (key == "height") {
            a.height = integer();
        } else if (key == "initial_frame") {
            a.initial_frame = integer();
        } else if (key == "final_frame") {
            a.final_frame = integer();
        } else if (key == "initial_clock") {
            a.initial_clock = number_value();
        } else if (key == "final_clock") {
            a.final_clock = number_value();
        } else if (key == "cyclic_animation") {
            a.cyclic = boolean();
        } else if (key == "library_path") {
            r.options.include_paths.push_back(ini.parent_path() / value);
        } else if (key == "declare") {
            const auto eq = value.find('=');
            if (eq == std::string::npos)
                throw std::runtime_error(place + ": Declare needs NAME=VALUE, not '" + value + "'");
            r.options.declares.emplace_back(trim(value.substr(0, eq)), trim(value.substr(eq + 1)));
        } else {
            r.warnings.push_back(place + ": setting '" + written + "' is ignored");
        }
    }
}

ResolvedScene resolve(const SceneArguments& arguments) {
    ResolvedScene r;
    std::string named_scene;  // a scene on the command line wins over Input_File_Name
    for (const auto& file : arguments.files) {
        if (is_ini(file)) {
            apply_ini_file(file, r);
        } else {
            if (!named_scene.empty())
                throw std::runtime_error("more than one scene named: " + named_scene + " and " + file);
            named_scene = file;
        }
    }
    if (!named_scene.empty()) r.scene = named_scene;
    if (r.scene.empty())
        throw std::runtime_error("no scene: name a .pov file or set Input_File_Name in an .ini file");
    auto& a = r.options.animation;
    if (arguments.width) a.width = *arguments.width;
    if (arguments.height) a.height = *arguments.height;
    if (arguments.frame_count) {
        a.initial_frame = 1;
        a.final_frame = *arguments.frame_count;
    }
    if (arguments.clock_range) {
        const std::string& text = *arguments.clock_range;
        const auto colon = text.find(':');
        try {
            std::size_t used = 0;
            if (colon == std::string::npos) {
                r.at_clock = std::stod(text, &used);
                if (used != text.size()) throw std::invalid_argument(text);
            } else {
                a.initial_clock = std::stod(text.substr(0, colon), &used);
                a.final_clock = std::stod(text.substr(colon + 1));
            }
        } catch (const std::exception&) {
            throw std::runtime_error("--clock needs A:B or a single value C, not '" + text + "'");
        }
    }
    if (arguments.cyclic) a.cyclic = true;
    if (arguments.shutter) a.shutter = *arguments.shutter;
    for (const auto& path : arguments.include_paths) r.options.include_paths.emplace_back(path);
    for (const auto& d : arguments.declares) {
        const auto eq = d.find('=');
        if (eq == std::string::npos || eq == 0)
            throw std::runtime_error("--declare needs NAME=VALUE, not '" + d + "'");
        r.options.declares.emplace_back(d.substr(0, eq), d.substr(eq + 1));
    }
    if (arguments.max_loop_iterations) r.options.max_loop_iterations = *arguments.max_loop_iterations;
    // A single clock value on a still is POV-Ray's +K: the still's clock.
    if (r.at_clock && !a.is_animation()) a.initial_clock = *r.at_clock;
    if (a.width < 1 || a.height < 1) throw std::runtime_error("the image size must be at least 1 by 1");
    if (a.final_frame < a.initial_frame)
        throw std::runtime_error("the final frame comes before the initial frame");
    if (a.shutter < 0 || a.shutter > 1) throw std::runtime_error("--shutter must lie in [0, 1]");
    return r;
}

}  // namespace hexant::app
