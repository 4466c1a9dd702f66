#include "language/povray_options.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "language/source_files.hpp"

namespace hexant::language {

std::string ascii_lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

std::string trim_blanks(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r\f\v");
    if (b == std::string::npos) return {};
    const auto e = s.find_last_not_of(" \t\r\f\v");
    return s.substr(b, e - b + 1);
}

namespace {

namespace fs = std::filesystem;

std::string upper(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    return s;
}

// What hexant does with an option: each its own field of PovRaySettings,
// or Ignored (a POV-Ray 3.7 option hexant has no use for: a warning).
enum class Option {
    InputFile,
    OutputFile,
    OutputToFile,
    OutputFileType,
    BitsPerColour,
    Width,
    Height,
    Clock,
    InitialFrame,
    FinalFrame,
    InitialClock,
    FinalClock,
    SubsetStart,
    SubsetEnd,
    FrameStep,
    Cyclic,
    LibraryPath,
    Declare,
    Display,
    Antialias,
    AntialiasThreshold,
    SamplingMethod,
    AntialiasDepth,
    Jitter,
    JitterAmount,
    ContinueTrace,
    Quality,
    Version,
    WorkThreads,
    Ignored,
    None,  // (a switch's sign or value that sets nothing)
};

// POV-Ray 3.7's .ini keys (frontend/processrenderoptions.cpp,
// RenderOptions_INI_Table), each with what hexant does with it.
struct Key {
    const char* name;
    Option option;
};
constexpr Key kKeys[] = {
    {"Input_File_Name", Option::InputFile},
    {"Output_File_Name", Option::OutputFile},
    {"Output_To_File", Option::OutputToFile},
    {"Output_File_Type", Option::OutputFileType},
    {"Bits_Per_Color", Option::BitsPerColour},
    {"Bits_Per_Colour", Option::BitsPerColour},
    {"Width", Option::Width},
    {"Height", Option::Height},
    {"Clock", Option::Clock},
    {"Initial_Frame", Option::InitialFrame},
    {"Final_Frame", Option::FinalFrame},
    {"Initial_Clock", Option::InitialClock},
    {"Final_Clock", Option::FinalClock},
    {"Subset_Start_Frame", Option::SubsetStart},
    {"Subset_End_Frame", Option::SubsetEnd},
    {"Frame_Step", Option::FrameStep},
    {"Cyclic_Animation", Option::Cyclic},
    {"Library_Path", Option::LibraryPath},
    {"Declare", Option::Declare},
    {"Display", Option::Display},
    {"Antialias", Option::Antialias},
    {"Antialias_Threshold", Option::AntialiasThreshold},
    {"Sampling_Method", Option::SamplingMethod},
    {"Antialias_Depth", Option::AntialiasDepth},
    {"Jitter", Option::Jitter},
    {"Jitter_Amount", Option::JitterAmount},
    {"Continue_Trace", Option::ContinueTrace},
    {"Quality", Option::Quality},
    {"Version", Option::Version},
    {"Work_Threads", Option::WorkThreads},
    // The rest: console streams, gamma, bounding, shell-outs, partial
    // renders, alpha, radiosity files and the like.
    {"All_Console", Option::Ignored},
    {"All_File", Option::Ignored},
    {"Antialias_Gamma", Option::Ignored},
    {"Append_File", Option::Ignored},
    {"Bounding", Option::Ignored},
    {"Bounding_Method", Option::Ignored},
    {"Bounding_Threshold", Option::Ignored},
    {"BSP_BaseAccessCost", Option::Ignored},
    {"BSP_ChildAccessCost", Option::Ignored},
    {"BSP_ISectCost", Option::Ignored},
    {"BSP_MaxDepth", Option::Ignored},
    {"BSP_MissChance", Option::Ignored},
    {"Buffer_Output", Option::Ignored},
    {"Buffer_Size", Option::Ignored},
    {"Clockless_Animation", Option::Ignored},
    {"Compression", Option::Ignored},
    {"Create_Histogram", Option::Ignored},
    {"Create_Ini", Option::Ignored},
    {"Debug_Console", Option::Ignored},
    {"Debug_File", Option::Ignored},
    {"Display_Gamma", Option::Ignored},
    {"Dither", Option::Ignored},
    {"Dither_Method", Option::Ignored},
    {"Draw_Vistas", Option::Ignored},
    {"End_Column", Option::Ignored},
    {"End_Row", Option::Ignored},
    {"Fatal_Console", Option::Ignored},
    {"Fatal_Error_Command", Option::Ignored},
    {"Fatal_Error_Return", Option::Ignored},
    {"Fatal_File", Option::Ignored},
    {"Field_Render", Option::Ignored},
    {"File_Gamma", Option::Ignored},
    {"Grayscale_Output", Option::Ignored},
    {"High_Reproducibility", Option::Ignored},
    {"Histogram_Name", Option::Ignored},
    {"Histogram_Grid_Size", Option::Ignored},
    {"Histogram_Type", Option::Ignored},
    {"Include_Header", Option::Ignored},
    {"Include_Ini", Option::Ignored},
    {"Light_Buffer", Option::Ignored},
    {"Max_Image_Buffer_Memory", Option::Ignored},
    {"Odd_Field", Option::Ignored},
    {"Output_Alpha", Option::Ignored},
    {"Palette", Option::Ignored},
    {"Pause_When_Done", Option::Ignored},
    {"Post_Frame_Command", Option::Ignored},
    {"Post_Frame_Return", Option::Ignored},
    {"Post_Scene_Command", Option::Ignored},
    {"Post_Scene_Return", Option::Ignored},
    {"Preview_End_Size", Option::Ignored},
    {"Preview_Start_Size", Option::Ignored},
    {"Pre_Frame_Command", Option::Ignored},
    {"Pre_Frame_Return", Option::Ignored},
    {"Pre_Scene_Command", Option::Ignored},
    {"Pre_Scene_Return", Option::Ignored},
    {"Radiosity_File_Name", Option::Ignored},
    {"Radiosity_From_File", Option::Ignored},
    {"Radiosity_To_File", Option::Ignored},
    {"Radiosity_Vain_Pretrace", Option::Ignored},
    {"Real_Time_Raytracing", Option::Ignored},
    {"Remove_Bounds", Option::Ignored},
    {"Render_Block_Size", Option::Ignored},
    {"Render_Block_Step", Option::Ignored},
    {"Render_Console", Option::Ignored},
    {"Render_File", Option::Ignored},
    {"Render_Pattern", Option::Ignored},
    {"Split_Unions", Option::Ignored},
    {"Start_Column", Option::Ignored},
    {"Start_Row", Option::Ignored},
    {"Statistic_Console", Option::Ignored},
    {"Statistic_File", Option::Ignored},
    {"Test_Abort_Count", Option::Ignored},
    {"Test_Abort", Option::Ignored},
    {"User_Abort_Command", Option::Ignored},
    {"User_Abort_Return", Option::Ignored},
    {"Verbose", Option::Ignored},
    {"Video_Mode", Option::Ignored},
    {"Vista_Buffer", Option::Ignored},
    {"Warning_Console", Option::Ignored},
    {"Warning_File", Option::Ignored},
    {"Warning_Level", Option::Ignored},
};

// POV-Ray 3.7's switches (RenderOptions_Cmd_Table), in its order: the
// first whose letters begin the word and whose value is there exactly when
// it takes one is the switch (so +KFF4 is KFF, +KF1.5 KF and +K0.5 K).
// `value` is the option the rest of the word sets, `sign` the on/off
// option that + or - sets.
enum class Takes { Nothing, Value, MaybeValue };
struct Switch {
    const char* letters;
    Takes takes;
    Option value, sign;
};
constexpr Switch kSwitches[] = {
    {"AG", Takes::Value, Option::Ignored, Option::None},
    {"AM", Takes::Value, Option::SamplingMethod, Option::None},
    // +A0.3: the threshold is written from its 0 (so +A1 is no switch).
    {"A0", Takes::Value, Option::AntialiasThreshold, Option::Antialias},
    {"A", Takes::Nothing, Option::None, Option::Antialias},
    {"BM", Takes::Value, Option::Ignored, Option::None},
    {"BS", Takes::Value, Option::Ignored, Option::None},
    {"B", Takes::Nothing, Option::None, Option::Ignored},
    {"C", Takes::Nothing, Option::None, Option::ContinueTrace},
    // +D0T: a video mode and palette, which a display-less hexant needs not.
    {"D", Takes::MaybeValue, Option::None, Option::Display},
    {"EC", Takes::Value, Option::Ignored, Option::None},
    {"EF0", Takes::Value, Option::SubsetEnd, Option::None},
    {"EF", Takes::Value, Option::SubsetEnd, Option::None},
    {"EP", Takes::Value, Option::Ignored, Option::None},
    {"ER", Takes::Value, Option::Ignored, Option::None},
    {"F", Takes::MaybeValue, Option::OutputFileType, Option::OutputToFile},
    {"GA", Takes::MaybeValue, Option::Ignored, Option::Ignored},
    {"GD", Takes::MaybeValue, Option::Ignored, Option::Ignored},
    {"GF", Takes::MaybeValue, Option::Ignored, Option::Ignored},
    {"GI", Takes::Value, Option::Ignored, Option::None},
    {"GP", Takes::Nothing, Option::None, Option::Ignored},
    {"GR", Takes::MaybeValue, Option::Ignored, Option::Ignored},
    {"GS", Takes::MaybeValue, Option::Ignored, Option::Ignored},
    {"GW", Takes::MaybeValue, Option::Ignored, Option::Ignored},
    {"HI", Takes::Value, Option::Ignored, Option::None},
    {"HR", Takes::Nothing, Option::None, Option::Ignored},
    {"H", Takes::Value, Option::Height, Option::None},
    {"I", Takes::Value, Option::InputFile, Option::None},
    {"J", Takes::MaybeValue, Option::JitterAmount, Option::Jitter},
    {"KC", Takes::Nothing, Option::None, Option::Cyclic},
    {"KI", Takes::Value, Option::InitialClock, Option::None},
    {"KFF", Takes::Value, Option::FinalFrame, Option::None},
    {"KFI", Takes::Value, Option::InitialFrame, Option::None},
    {"KF", Takes::Value, Option::FinalClock, Option::None},
    {"KLA", Takes::Nothing, Option::None, Option::Ignored},
    {"K", Takes::Value, Option::Clock, Option::None},
    {"L", Takes::Value, Option::LibraryPath, Option::None},
    {"MB", Takes::MaybeValue, Option::Ignored, Option::Ignored},
    {"MI", Takes::Value, Option::Ignored, Option::None},
    {"MV", Takes::Value, Option::Version, Option::None},
    {"O", Takes::Value, Option::OutputFile, Option::None},
    {"P", Takes::Nothing, Option::None, Option::Ignored},
    {"Q", Takes::Value, Option::Quality, Option::None},
    {"RFI", Takes::Nothing, Option::None, Option::Ignored},
    {"RFO", Takes::Nothing, Option::None, Option::Ignored},
    {"RF", Takes::Value, Option::Ignored, Option::None},
    {"RS", Takes::Value, Option::Ignored, Option::None},
    {"RP", Takes::Value, Option::Ignored, Option::None},
    {"RTR", Takes::Nothing, Option::None, Option::Ignored},
    {"RVP", Takes::Nothing, Option::None, Option::Ignored},
    {"R", Takes::Value, Option::AntialiasDepth, Option::None},
    {"SC", Takes::Value, Option::Ignored, Option::None},
    {"SF0", Takes::Value, Option::SubsetStart, Option::None},
    {"SF", Takes::Value, Option::SubsetStart, Option::None},
    {"SP", Takes::Value, Option::Ignored, Option::None},
    {"SR", Takes::Value, Option::Ignored, Option::None},
    {"STP", Takes::Value, Option::FrameStep, Option::None},
    {"SU", Takes::Nothing, Option::None, Option::Ignored},
    {"TH", Takes::MaybeValue, Option::Ignored, Option::Ignored},
    {"UA", Takes::Nothing, Option::None, Option::Ignored},
    {"UD", Takes::Nothing, Option::None, Option::Ignored},
    {"UF", Takes::Nothing, Option::None, Option::Ignored},
    {"UL", Takes::Nothing, Option::None, Option::Ignored},
    {"UO", Takes::Nothing, Option::None, Option::Ignored},
    {"UR", Takes::Nothing, Option::None, Option::Ignored},
    {"UV", Takes::Nothing, Option::None, Option::Ignored},
    {"V", Takes::Nothing, Option::None, Option::Ignored},
    {"WL", Takes::Value, Option::Ignored, Option::None},
    {"WT", Takes::Value, Option::WorkThreads, Option::None},
    {"W", Takes::Value, Option::Width, Option::None},
    {"X", Takes::MaybeValue, Option::Ignored, Option::Ignored},
};

const Key* find_key(const std::string& key) {
    const std::string wanted = ascii_lower(trim_blanks(key));
    for (const Key& k : kKeys)
        if (ascii_lower(k.name) == wanted) return &k;
    return nullptr;
}

// The switch `body` (the word without its sign) is, and where its value
// begins.
const Switch* find_switch(const std::string& body, std::size_t& value_at) {
    const std::string u = upper(body);
    for (const Switch& s : kSwitches) {
        const std::string letters = s.letters;
        if (u.rfind(letters, 0) != 0) continue;
        const bool has_value = u.size() > letters.size();
        if ((has_value && s.takes == Takes::Nothing) || (!has_value && s.takes == Takes::Value))
            continue;
        value_at = letters.size();
        return &s;
    }
    return nullptr;
}

// The output types of POV-Ray 3.7 (+Fx, Output_File_Type=x); hexant writes
// all but JPEG and the system's own (app/povray_render_options.cpp).
const char* output_type_name(char letter) {
    switch (letter) {
        case 'N':
            return "PNG";
        case 'E':
            return "OpenEXR";
        case 'T':
            return "Targa";
        case 'C':
            return "compressed Targa";
        case 'J':
            return "JPEG";
        case 'P':
            return "PPM";
        case 'B':
            return "BMP";
        case 'H':
            return "Radiance HDR";
        case 'S':
            return "the system's own format";
        default:
            return nullptr;
    }
}

// Sets options from one line's switch or option, naming it in messages.
class Setter {
  public:
    // `written`: the switch word, or the option's Key=Value; `name`: what
    // a warning calls it (the word, or the key).
    Setter(PovRaySettings& settings, const std::string& place, const fs::path& folder,
           const std::string& written, const std::string& name, bool from_switch)
        : s_(settings),
          place_(place),
          folder_(folder),
          written_(written),
          name_(name),
          from_switch_(from_switch) {}

    void set(Option option, const std::string& value);
    void set_on(Option option, bool on);
    void ignored() {
        s_.warnings.push_back((place_.empty() ? "command line" : place_) + ": " +
                              (from_switch_ ? "switch '" : "option '") + name_ + "' is ignored");
    }

  private:
    std::string source() const { return place_.empty() ? written_ : place_ + ": " + written_; }
    template <class T>
    Given<T> given(T value) const {
        return {std::move(value), source()};
    }

    [[noreturn]] void bad(const std::string& message) const {
        throw std::runtime_error((place_.empty() ? "" : place_ + ": ") + written_ + ": " + message);
    }
    [[noreturn]] void needs(const std::string& what, const std::string& value) const {
        throw std::runtime_error((place_.empty() ? "" : place_ + ": ") + name_ + " needs " + what +
                                 ", not '" + value + "'");
    }

    int integer(const std::string& value) const {
        const char* begin = value.data() + (value.rfind('+', 0) == 0 ? 1 : 0);
        const char* end = value.data() + value.size();
        int v = 0;
        const auto [stop, error] = std::from_chars(begin, end, v);
        if (value.empty() || error != std::errc() || stop != end) needs("a whole number", value);
        return v;
    }

    double real(const std::string& value) const {
        char* stop = nullptr;
        const double v = std::strtod(value.c_str(), &stop);
        if (value.empty() || stop != value.c_str() + value.size() || !std::isfinite(v) ||
            std::isspace(static_cast<unsigned char>(value[0])))
            needs("a number", value);
        return v;
    }

    bool boolean(const std::string& value) const {
        const std::string v = ascii_lower(value);
        if (v == "on" || v == "true" || v == "yes" || v == "1") return true;
        if (v == "off" || v == "false" || v == "no" || v == "0") return false;
        needs("on or off", value);
    }

    fs::path path(const std::string& value, const char* what) const {
        if (value.empty()) needs(what, value);
        return folder_ / value;
    }

    void output_type(const std::string& value);

    PovRaySettings& s_;
    const std::string& place_;
    const fs::path& folder_;
    std::string written_, name_;
    bool from_switch_;
};

void Setter::output_type(const std::string& value) {
    // Output_File_Type=x is one letter; +Fx may add the bits per colour
    // (+FN16) or g for grey (+FNg).
    if (value.empty() || (!from_switch_ && value.size() != 1))
        needs("one letter (N: PNG, E: OpenEXR, T: Targa, ...)", value);
    const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(value[0])));
    const char* name = output_type_name(letter);
    if (!name)
        bad(std::string("'") + value[0] +
            "' is not a POV-Ray output type (B, C, E, H, J, N, P, S or T)");
    if (letter == 'J')
        bad("hexant does not write frames as JPEG: a frame is read back after it is written and "
            "must read as written (a full disk shows so; --resume trusts it), which a lossy "
            "format cannot; +FN (PNG) is lossless");
    if (letter == 'S') bad("POV-Ray 3.7 on Unix has no system output format (+FS); +FN writes PNG");
    const std::string rest = value.substr(1);
    if (rest == "g" || rest == "G") bad("hexant writes colour frames only, not grey ones");
    if (!rest.empty()) {
        if (rest.find_first_not_of("0123456789") != std::string::npos)
            needs("a type letter and perhaps its bits per colour (+FN8)", value);
        s_.bits_per_colour = given(integer(rest));
    }
    s_.output_type = given(letter);
}

void Setter::set(Option option, const std::string& value) {
    switch (option) {
        case Option::InputFile:
            s_.input_file = path(value, "a file name");
            break;
        case Option::OutputFile: {
            const fs::path file = path(value, "a file name");
            // An .ini travels with a downloaded scene: it may name the
            // frames' files in its own folder, not elsewhere (issue 45's
            // rule for Library_Path); the command line's +O may.
            if (!place_.empty()) {
                std::error_code error;
                const fs::path real = fs::weakly_canonical(fs::absolute(file, error), error);
                const fs::path root = fs::weakly_canonical(
                    fs::absolute(folder_.empty() ? "." : folder_, error), error);
                if (!lies_in(real, root))
                    bad("outside the .ini file's folder: refused (an .ini may not choose where "
                        "files are written; +O or -o on the command line may)");
            }
            s_.output_file = given(file);
            break;
        }
        case Option::OutputToFile:
            s_.output_to_file = given(boolean(value));
            break;
        case Option::OutputFileType:
            output_type(value);
            break;
        case Option::BitsPerColour:
            s_.bits_per_colour = given(integer(value));
            break;
        case Option::Width:
            s_.width = integer(value);
            break;
        case Option::Height:
            s_.height = integer(value);
            break;
        case Option::Clock:
            s_.clock = given(real(value));
            break;
        case Option::InitialFrame:
            s_.initial_frame = integer(value);
            break;
        case Option::FinalFrame:
            s_.final_frame = integer(value);
            break;
        case Option::InitialClock:
            s_.initial_clock = real(value);
            break;
        case Option::FinalClock:
            s_.final_clock = real(value);
            break;
        case Option::SubsetStart:
            s_.subset_start = given(real(value));
            break;
        case Option::SubsetEnd:
            s_.subset_end = given(real(value));
            break;
        case Option::FrameStep:
            s_.frame_step = given(integer(value));
            break;
        case Option::Cyclic:
            s_.cyclic = boolean(value);
            break;
        case Option::LibraryPath:
            s_.library_paths.push_back(path(value, "a folder"));
            s_.library_path_places.push_back(place_.empty() ? written_ : place_);
            break;
        case Option::Declare: {
            const auto eq = value.find('=');
            const std::string name =
                eq == std::string::npos ? "" : trim_blanks(value.substr(0, eq));
            const std::string text =
                eq == std::string::npos ? "" : trim_blanks(value.substr(eq + 1));
            if (name.empty() || text.empty()) needs("NAME=VALUE", value);
            s_.declares.emplace_back(name, text);
            break;
        }
        case Option::Display:
            s_.display = given(boolean(value));
            break;
        case Option::Antialias:
            s_.antialias = given(boolean(value));
            break;
        case Option::AntialiasThreshold:
            s_.antialias_threshold = given(real(value));
            break;
        case Option::SamplingMethod:
            s_.sampling_method = given(integer(value));
            break;
        case Option::AntialiasDepth:
            s_.antialias_depth = given(integer(value));
            break;
        case Option::Jitter:
            s_.jitter = given(boolean(value));
            break;
        case Option::JitterAmount:
            s_.jitter_amount = given(real(value));
            break;
        case Option::ContinueTrace:
            s_.continue_trace = given(boolean(value));
            break;
        case Option::Quality:
            s_.quality = given(integer(value));
            break;
        case Option::Version:
            s_.version = given(real(value));
            break;
        case Option::WorkThreads:
            s_.work_threads = given(integer(value));
            break;
        case Option::Ignored:
            ignored();
            break;
        case Option::None:
            break;
    }
}

void Setter::set_on(Option option, bool on) {
    const auto flag = [&](std::optional<Given<bool>>& field) { field = given(on); };
    switch (option) {
        case Option::OutputToFile:
            return flag(s_.output_to_file);
        case Option::Cyclic:
            s_.cyclic = on;
            return;
        case Option::Display:
            return flag(s_.display);
        case Option::Antialias:
            return flag(s_.antialias);
        case Option::Jitter:
            return flag(s_.jitter);
        case Option::ContinueTrace:
            return flag(s_.continue_trace);
        default:
            return;
    }
}

}  // namespace

bool apply_povray_switch(const std::string& word, const std::string& place, const fs::path& folder,
                         PovRaySettings& settings) {
    if (word.size() < 2 || (word[0] != '+' && word[0] != '-')) return false;
    const std::string body = word.substr(1);
    std::size_t value_at = 0;
    const Switch* s = find_switch(body, value_at);
    if (!s) return false;
    Setter setter(settings, place, folder, word, word, true);
    if (s->value == Option::Ignored || s->sign == Option::Ignored) {
        setter.ignored();
        return true;
    }
    if (s->sign != Option::None) setter.set_on(s->sign, word[0] == '+');
    if (s->value != Option::None && value_at < body.size())
        setter.set(s->value, body.substr(value_at));
    return true;
}

bool apply_povray_option(const std::string& key, const std::string& value, const std::string& place,
                         const fs::path& folder, PovRaySettings& settings) {
    const Key* k = find_key(key);
    if (!k) return false;
    Setter(settings, place, folder, trim_blanks(key) + "=" + value, trim_blanks(key), false)
        .set(k->option, value);
    return true;
}

bool is_povray_option_key(const std::string& key) {
    return find_key(key) != nullptr;
}

bool is_povray_switch(const std::string& body) {
    std::size_t value_at = 0;
    return !body.empty() && find_switch(body, value_at) != nullptr;
}

void overlay(PovRaySettings& s, const PovRaySettings& later) {
    const auto over = [](auto& field, const auto& value) {
        if (value) field = value;
    };
    over(s.input_file, later.input_file);
    over(s.width, later.width);
    over(s.height, later.height);
    over(s.initial_frame, later.initial_frame);
    over(s.final_frame, later.final_frame);
    over(s.initial_clock, later.initial_clock);
    over(s.final_clock, later.final_clock);
    over(s.cyclic, later.cyclic);
    over(s.clock, later.clock);
    over(s.version, later.version);
    over(s.output_file, later.output_file);
    over(s.output_to_file, later.output_to_file);
    over(s.output_type, later.output_type);
    over(s.bits_per_colour, later.bits_per_colour);
    over(s.subset_start, later.subset_start);
    over(s.subset_end, later.subset_end);
    over(s.frame_step, later.frame_step);
    over(s.antialias, later.antialias);
    over(s.antialias_threshold, later.antialias_threshold);
    over(s.sampling_method, later.sampling_method);
    over(s.antialias_depth, later.antialias_depth);
    over(s.jitter, later.jitter);
    over(s.jitter_amount, later.jitter_amount);
    over(s.continue_trace, later.continue_trace);
    over(s.quality, later.quality);
    over(s.display, later.display);
    over(s.work_threads, later.work_threads);
    const auto append = [](auto& into, const auto& more) {
        into.insert(into.end(), more.begin(), more.end());
    };
    append(s.library_paths, later.library_paths);
    append(s.library_path_places, later.library_path_places);
    append(s.declares, later.declares);
    append(s.warnings, later.warnings);
}

std::vector<std::string> render_only_sources(const PovRaySettings& s) {
    std::vector<std::string> sources;
    const auto add = [&](const auto& field) {
        // (+A0.3 sets two options: named once.)
        if (field && std::find(sources.begin(), sources.end(), field->source) == sources.end())
            sources.push_back(field->source);
    };
    add(s.output_file);
    add(s.output_to_file);
    add(s.output_type);
    add(s.bits_per_colour);
    add(s.subset_start);
    add(s.subset_end);
    add(s.frame_step);
    add(s.antialias);
    add(s.antialias_threshold);
    add(s.sampling_method);
    add(s.antialias_depth);
    add(s.jitter);
    add(s.jitter_amount);
    add(s.continue_trace);
    add(s.quality);
    add(s.display);
    add(s.work_threads);
    return sources;
}

}  // namespace hexant::language
