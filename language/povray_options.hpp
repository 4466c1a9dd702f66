// POV-Ray 3.7's options: one table for the `Key=Value` options of an .ini
// file (or of the command line) and for the switches that set the same
// options (`+W320`, `-KC`, `+A0.3`), as POV-Ray's own
// frontend/processrenderoptions.cpp lists both against one set of
// attributes. Meanings: POV-Ray 3.7's reference, section 3.2 "Command-line
// and INI-file Options". What hexant makes of each:
//   read here: Input_File_Name (+I), Width (+W), Height (+H), Initial_Frame
//     (+KFI), Final_Frame (+KFF), Initial_Clock (+KI), Final_Clock (+KF),
//     Clock (+K), Cyclic_Animation (+KC), Library_Path (+L), Declare,
//     Version (+MV);
//   kept for `render` (app/povray_render_options.hpp maps them onto its
//     flags): Output_File_Name (+O), Output_To_File (+F/-F),
//     Output_File_Type (+Fx), Bits_Per_Color (+Fxn), Subset_Start_Frame
//     (+SF), Subset_End_Frame (+EF), Frame_Step (+STP), Antialias (+A/-A),
//     Antialias_Threshold (+An.n), Sampling_Method (+AM), Antialias_Depth
//     (+R), Jitter (+J/-J), Jitter_Amount (+Jn.n), Continue_Trace (+C),
//     Quality (+Q), Display (+D/-D), Work_Threads (+WT);
//   every other POV-Ray 3.7 option or switch: ignored with a warning.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace hexant::language {

// ASCII lower case (POV-Ray's option keys, switches and .ini labels are
// case-blind) and a string without its leading and trailing blanks: for
// this table and the .ini reader alike.
std::string ascii_lower(std::string s);
std::string trim_blanks(const std::string& s);

// A value and where it was given, for the notes and errors that name it:
// the switch or option as written, after its place ("+A0.3" on the command
// line, "res.ini:4: Antialias=on" in a file).
template <class T>
struct Given {
    T value{};
    std::string source;
};

// What one .ini file, or one command-line word, sets; an option it does
// not mention stays empty. Relative paths are taken from the .ini file's
// folder (the current folder on the command line).
struct PovRaySettings {
    std::optional<std::filesystem::path> input_file;
    std::optional<int> width, height;
    std::optional<int> initial_frame, final_frame;
    std::optional<double> initial_clock, final_clock;
    std::optional<bool> cyclic;
    std::vector<std::filesystem::path> library_paths;           // in order; they accumulate
    std::vector<std::string> library_path_places;               // "FILE:LINE" of each
    std::vector<std::pair<std::string, std::string>> declares;  // NAME, VALUE
    std::optional<Given<double>> clock;                         // a still's clock
    std::optional<Given<double>> version;                       // the language's, at the start
    // For `render` (app/povray_render_options.hpp).
    std::optional<Given<std::filesystem::path>> output_file;
    std::optional<Given<bool>> output_to_file;
    // 'N' (PNG), 'E' (OpenEXR), 'T' (Targa), 'C' (RLE Targa), 'P' (PPM),
    // 'B' (BMP) or 'H' (Radiance HDR).
    std::optional<Given<char>> output_type;
    std::optional<Given<int>> bits_per_colour;
    // A frame number, or below 1 a fraction of the frames (POV-Ray's rule).
    std::optional<Given<double>> subset_start, subset_end;
    std::optional<Given<int>> frame_step;
    std::optional<Given<bool>> antialias;
    std::optional<Given<double>> antialias_threshold;
    std::optional<Given<int>> sampling_method, antialias_depth;
    std::optional<Given<bool>> jitter;
    std::optional<Given<double>> jitter_amount;
    std::optional<Given<bool>> continue_trace;
    std::optional<Given<int>> quality;
    std::optional<Given<bool>> display;
    std::optional<Given<int>> work_threads;
    std::vector<std::string> warnings;  // "PLACE: ..." for what is ignored
};

// Sets one switch word ("+W320", "-KC", "+FN", "+A0.3"), matched as POV-Ray
// 3.7 matches them: letters in any case, the first entry of its switch
// table whose letters begin the word and that takes a value exactly when
// one follows. The sign turns an on/off option on or off (-KC, -A, -D)
// and means nothing to a value (-W320 is +W320). `place` begins messages
// ("res.ini:4"; empty on the command line). Returns false for a word that
// is no POV-Ray 3.7 switch. Throws std::runtime_error naming the place and
// the switch for a bad value, or for what hexant cannot do at all (an
// output type it does not write: +FJ, +FS).
bool apply_povray_switch(const std::string& word, const std::string& place,
                         const std::filesystem::path& folder, PovRaySettings& settings);

// Sets one `Key=Value` option (the key in any case). Returns false for a
// key that is not POV-Ray 3.7's. Throws as apply_povray_switch.
bool apply_povray_option(const std::string& key, const std::string& value, const std::string& place,
                         const std::filesystem::path& folder, PovRaySettings& settings);

// Whether `key` names a POV-Ray 3.7 option (any case), and whether `word`
// (without its sign) is one of its switches.
bool is_povray_option_key(const std::string& key);
bool is_povray_switch(const std::string& letters_and_value);

// `later` over `settings`: what later sets replaces; library paths,
// declarations and warnings append.
void overlay(PovRaySettings& settings, const PovRaySettings& later);

// The options given that only `render` uses, by their sources (for a note
// from `check` and `dump`, which render nothing).
std::vector<std::string> render_only_sources(const PovRaySettings& settings);

}  // namespace hexant::language
