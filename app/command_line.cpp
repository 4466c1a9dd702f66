#include "app/command_line.hpp"

#include <algorithm>
#include <cmath>
#include <new>
#include <ostream>
#include <stdexcept>

#include "app/povray_words.hpp"
#include "language/scene_error.hpp"
#include "language/source_files.hpp"

namespace hexant::app {

void add_scene_arguments(CLI::App& command, SceneArguments& a) {
    command
        .add_option("files", a.files,
                    "The scene (.pov), POV-Ray .ini files, POV-Ray 3.7 switches (+W640 +KFF60 "
                    "-D ...) and Key=Value options, applied in order; the flags below override "
                    "them")
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
    command.add_option(
        "--shutter-curve", a.shutter_curve,
        "How open the shutter is over its open time, weighting the samples' times: box "
        "(the default), triangle, trapezoid, or keys u:w,u:w,... (u from 0 to 1 of the "
        "open time, w >= 0; e.g. 0:0,0.1:1,0.9:1,1:0)");
    command.add_option(
        "--rolling-shutter", a.rolling_shutter,
        "Rolling shutter: the fraction of each frame's clock step from the top row's "
        "opening to the bottom row's (default 0, every row at once)");
    command.add_option(
        "--shutter-position", a.shutter_position,
        "Where each frame's exposure sits against the frame's clock: start (opens at it, the "
        "default), centre (centred on it) or end (closes at it)");
    command.add_flag("--shutter-beyond-range", a.shutter_beyond_range,
                     "Let a non-cyclic animation's first and last exposures reach outside "
                     "[Initial_Clock, Final_Clock] (otherwise they are cut to it)");
    command.add_option("-L,--include-path", a.include_paths,
                       "Folder searched for #include after the scene's own (POV-Ray's +L)");
    command.add_option("--allow-read", a.read_paths,
                       "Folder #include may also read from (POV-Ray's Read_Paths); otherwise only "
                       "the scene's folder, -L folders and the include folders");
    command.add_option("--allow-write", a.write_paths,
                       "Folder #fopen may also write to (POV-Ray's Write_Paths); otherwise only "
                       "the scene's output folder, that of -o (out/SCENE by default)");
    command.add_flag("--strict", a.strict,
                     "Every warning an error at its place: refuse a scene that uses what hexant "
                     "does not render as POV-Ray does");
    command.add_option("--declare", a.declares,
                       "NAME=VALUE, as POV-Ray's Declare=: a number, a vector <a, b, c> or a "
                       "\"string\"");
    // The limits (language/limits.hpp). Each is a range, so that "-1"
    // (which an unsigned conversion wraps to 2^64 - 1) is refused rather
    // than taken as no limit at all.
    command
        .add_option("--max-loop-iterations", a.max_loop_iterations,
                    "Stop a #while or #for after this many iterations (default 10^7)")
        ->check(CLI::Range(std::size_t(1), std::size_t(1'000'000'000'000)));
    command
        .add_option("--max-iterations", a.max_iterations,
                    "Stop the scene after this many loop iterations and macro calls in all "
                    "(default 10^8)")
        ->check(CLI::Range(std::size_t(1), std::size_t(1'000'000'000'000)));
    command
        .add_option("--max-time-pieces", a.max_time_pieces,
                    "Pieces of time a condition that depends on clock may split the "
                    "animation into (default 10^4)")
        ->check(CLI::Range(std::size_t(1), std::size_t(1'000'000'000)));
    command
        .add_option("--max-text-read", a.max_text_read,
                    "Bytes of scene text read in all, each loop turn and macro call reading "
                    "its body again (default 1073741824, 1 GiB)")
        ->check(CLI::Range(std::size_t(1), std::size_t(1) << 50));
    command
        .add_option("--max-macro-depth", a.max_macro_depth,
                    "Macro calls nested at most this deep (default 200)")
        ->check(CLI::Range(1, 100'000));
    command
        .add_option("--max-include-depth", a.max_include_depth,
                    "#include nested at most this deep (default 100)")
        ->check(CLI::Range(1, 10'000));
    command
        .add_option("--max-string-length", a.max_string_length,
                    "Characters of one string (default 16777216, 16 Mi)")
        ->check(CLI::Range(std::size_t(1), std::size_t(1) << 40));
    command
        .add_option("--max-debug-output", a.max_debug_output,
                    "Bytes of #debug text a scene may print (default 67108864, 64 MiB)")
        ->check(CLI::Range(std::size_t(1), std::size_t(1) << 40));
    command
        .add_option(
            "--max-array-memory", a.max_array_memory_mib,
            "MiB the scene's arrays and its variables' strings may hold at once (default 2048)")
        ->check(CLI::Range(std::size_t(1), std::size_t(1) << 30));
    command
        .add_option("--max-objects", a.max_objects,
                    "Objects a scene may make, each CSG member and each copy counted "
                    "(default 10^6)")
        ->check(CLI::Range(std::uint64_t(1), std::uint64_t(1) << 40));
    command
        .add_option("--max-triangles", a.max_triangles,
                    "Triangles the scene's meshes may hold in all (default 4*10^6)")
        ->check(CLI::Range(std::uint64_t(1), std::uint64_t(1) << 40));
    command.add_option("--max-frames", a.max_frames, "Frames an animation may have (default 10^6)")
        ->check(CLI::Range(1LL, 2'000'000'000LL));
    command
        .add_option("--max-pixels", a.max_pixels,
                    "Pixels (width times height) an image may have (default 10^8)")
        ->check(CLI::Range(1LL, 1LL << 40));
}

namespace {

double full_number(const std::string& text) {
    std::size_t used = 0;
    const double v = std::stod(text, &used);
    if (used != text.size()) throw std::invalid_argument(text);
    return v;
}

// A Library_Path or +L folder, where it was given.
struct LibraryFolder {
    std::filesystem::path folder;
    std::string place;
    bool from_ini;
};

// The library folders in order, those of the .ini files only if a scene
// may read from them: inside the scene's folder, an --allow-read folder or
// POV-Ray's include folder. An .ini travels with a downloaded scene, so its
// Library_Path=/etc must not widen what the scene reads (issue 45); one
// outside is left out of the search, with a warning naming its line. A +L
// on the command line is the user's own, as -L.
std::vector<std::filesystem::path> confined_library_paths(
    const std::vector<LibraryFolder>& given, const std::filesystem::path& scene,
    const std::vector<std::filesystem::path>& allowed_reads, std::vector<std::string>& warnings) {
    namespace fs = std::filesystem;
    std::error_code error;
    std::vector<fs::path> roots{fs::absolute(scene, error).parent_path(),
                                language::kPovRayIncludeDir};
    roots.insert(roots.end(), allowed_reads.begin(), allowed_reads.end());
    for (auto& root : roots) root = fs::weakly_canonical(root.empty() ? "." : root, error);
    std::vector<fs::path> kept;
    for (const auto& [folder, place, from_ini] : given) {
        const fs::path real = fs::weakly_canonical(folder, error);
        const bool inside =
            !from_ini || std::any_of(roots.begin(), roots.end(), [&](const fs::path& root) {
                return language::lies_in(real, root);
            });
        if (inside)
            kept.push_back(folder);
        else
            warnings.push_back(place + ": Library_Path " + folder.string() +
                               " is outside the scene's folder: not searched (an .ini may not "
                               "widen what a scene reads; --allow-read " +
                               folder.string() + " allows it)");
    }
    return kept;
}

// What one command-line word that is no .ini file and no scene sets: a
// POV-Ray switch or Key=Value option; none for any other word.
std::optional<language::PovRaySettings> povray_word(const std::string& word) {
    language::PovRaySettings one;
    if (const auto minus = minus_switch(word)) {
        if (!language::apply_povray_switch(*minus, "", "", one))
            throw std::runtime_error(*minus + ": not a POV-Ray 3.7 switch");
        return one;
    }
    if (word.size() >= 2 && word[0] == '+') {
        if (!language::apply_povray_switch(word, "", "", one))
            throw std::runtime_error(word +
                                     ": not a POV-Ray 3.7 switch (hexant's own flags begin "
                                     "with --: `hexant render --help` lists them)");
        return one;
    }
    const auto eq = word.find('=');
    if (eq == std::string::npos || eq == 0 || !language::is_povray_option_key(word.substr(0, eq)))
        return std::nullopt;
    language::apply_povray_option(word.substr(0, eq), word.substr(eq + 1), "", "", one);
    return one;
}

}  // namespace

ResolvedScene resolve(const SceneArguments& arguments) {
    ResolvedScene r;
    std::string named_scene;   // a scene on the command line wins over Input_File_Name
    std::string scene_switch;  // ... but not over +I or Input_File_Name= there
    std::vector<LibraryFolder> library;
    for (const auto& word : arguments.files) {
        language::PovRaySettings one;
        const auto ini = language::ini_reference(word);
        if (ini) {
            one = language::read_ini_file(ini->file, ini->section);
            std::error_code error;
            if (auto real = std::filesystem::canonical(ini->file, error); !error)
                r.ini_files.push_back(std::move(real));
        } else if (auto settings = povray_word(word)) {
            one = std::move(*settings);
            if (one.input_file) scene_switch = minus_switch(word).value_or(word);
        } else {
            if (!named_scene.empty())
                throw std::runtime_error("more than one scene named: " + named_scene + " and " +
                                         word);
            named_scene = word;
            continue;
        }
        // (Confined below, once the scene and --allow-read are known.)
        for (std::size_t i = 0; i < one.library_paths.size(); ++i)
            library.push_back({one.library_paths[i], one.library_path_places.at(i), bool(ini)});
        one.library_paths.clear();
        one.library_path_places.clear();
        language::overlay(r.povray, one);
    }
    if (!named_scene.empty() && !scene_switch.empty())
        throw std::runtime_error("more than one scene named: " + named_scene + " and " +
                                 scene_switch);
    language::apply_ini_settings(r.povray, r.options, r.scene);
    r.warnings = r.povray.warnings;
    if (r.povray.clock) r.at_clock = r.povray.clock->value;
    if (!named_scene.empty()) r.scene = named_scene;
    if (r.scene.empty())
        throw std::runtime_error(
            "no scene: name a .pov file (or +Iscene.pov), or set Input_File_Name in an .ini file");
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
        r.at_clock.reset();  // (over +K or Clock=)
        try {
            if (colon == std::string::npos) {
                r.at_clock = full_number(text);
            } else {
                a.initial_clock = full_number(text.substr(0, colon));
                a.final_clock = full_number(text.substr(colon + 1));
            }
        } catch (const std::exception&) {
            throw std::runtime_error("--clock needs A:B or a single value C, not '" + text + "'");
        }
    }
    if (arguments.cyclic) a.cyclic = true;
    if (arguments.shutter) a.shutter = *arguments.shutter;
    if (arguments.shutter_curve) {
        try {
            a.shutter_curve = runtime::ShutterCurve::parse(*arguments.shutter_curve);
        } catch (const std::invalid_argument& e) {
            throw std::runtime_error(std::string("--shutter-curve: ") + e.what());
        }
    }
    if (arguments.rolling_shutter) a.rolling_shutter = *arguments.rolling_shutter;
    if (arguments.shutter_position) {
        const std::string& p = *arguments.shutter_position;
        if (p == "start")
            a.shutter_position = runtime::ShutterPosition::Start;
        else if (p == "centre" || p == "center")
            a.shutter_position = runtime::ShutterPosition::Centre;
        else if (p == "end")
            a.shutter_position = runtime::ShutterPosition::End;
        else
            throw std::runtime_error("--shutter-position needs start, centre or end, not '" + p +
                                     "'");
    }
    if (arguments.shutter_beyond_range) a.shutter_beyond_range = true;
    for (const auto& path : arguments.read_paths) r.options.read_paths.emplace_back(path);
    r.options.include_paths =
        confined_library_paths(library, r.scene, r.options.read_paths, r.warnings);
    for (const auto& path : arguments.include_paths) r.options.include_paths.emplace_back(path);
    for (const auto& path : arguments.write_paths) r.options.write_paths.emplace_back(path);
    // The default output folder, as render's default -o (render sets its own).
    r.options.output_folder = std::filesystem::path("out") / std::filesystem::path(r.scene).stem();
    r.options.strict = arguments.strict;
    for (const auto& d : arguments.declares) {
        const auto eq = d.find('=');
        if (eq == std::string::npos || eq == 0)
            throw std::runtime_error("--declare needs NAME=VALUE, not '" + d + "'");
        r.options.declares.emplace_back(d.substr(0, eq), d.substr(eq + 1));
    }
    auto& limits = r.options.limits;
    if (arguments.max_loop_iterations) limits.loop_iterations = *arguments.max_loop_iterations;
    if (arguments.max_iterations) limits.total_iterations = *arguments.max_iterations;
    if (arguments.max_time_pieces) limits.time_pieces = *arguments.max_time_pieces;
    if (arguments.max_text_read) limits.text_read = *arguments.max_text_read;
    if (arguments.max_macro_depth) limits.macro_depth = *arguments.max_macro_depth;
    if (arguments.max_include_depth) limits.include_depth = *arguments.max_include_depth;
    if (arguments.max_string_length) limits.string_length = *arguments.max_string_length;
    if (arguments.max_array_memory_mib) limits.array_memory = *arguments.max_array_memory_mib << 20;
    if (arguments.max_debug_output) limits.debug_output = *arguments.max_debug_output;
    if (arguments.max_objects) limits.objects = *arguments.max_objects;
    if (arguments.max_triangles) limits.triangles = *arguments.max_triangles;
    if (arguments.max_frames) limits.frames = *arguments.max_frames;
    if (arguments.max_pixels) limits.image_pixels = *arguments.max_pixels;
    // A single clock value on a still is POV-Ray's +K: the still's clock.
    if (r.at_clock && !a.is_animation()) {
        a.initial_clock = *r.at_clock;
        a.clock_given = true;
    }
    if (a.width < 1 || a.height < 1)
        throw std::runtime_error("the image size must be at least 1 by 1");
    // Checked here, before any pixel is allocated: -W 100000 -H 100000
    // ended in std::bad_alloc with no word of why.
    if (static_cast<long long>(a.width) * a.height > limits.image_pixels)
        throw std::runtime_error("an image of " + std::to_string(a.width) + " by " +
                                 std::to_string(a.height) + " pixels is more than the limit of " +
                                 std::to_string(limits.image_pixels) +
                                 " pixels (--max-pixels N raises it)");
    if (a.final_frame < a.initial_frame)
        throw std::runtime_error("the final frame comes before the initial frame");
    // Frames are counted in int and each frame's eye and lights are placed
    // up front: a count near 2^31 overflowed the loop over frames and took
    // seconds before the first pixel. Computed in long long: the count of
    // frames INT_MIN to INT_MAX does not fit an int.
    if (static_cast<long long>(a.final_frame) - a.initial_frame >= limits.frames)
        throw std::runtime_error("an animation of more than " + std::to_string(limits.frames) +
                                 " frames (frames " + std::to_string(a.initial_frame) + " to " +
                                 std::to_string(a.final_frame) +
                                 "; --max-frames N raises the limit)");
    // Written so that NaN fails too (every comparison with NaN is false).
    if (!(a.shutter >= 0 && a.shutter <= 1))
        throw std::runtime_error("--shutter must lie in [0, 1]");
    if (!(a.rolling_shutter >= 0 && a.rolling_shutter <= 1))
        throw std::runtime_error("--rolling-shutter must lie in [0, 1]");
    if (!std::isfinite(a.initial_clock) || !std::isfinite(a.final_clock) ||
        (r.at_clock && !std::isfinite(*r.at_clock)))
        throw std::runtime_error(
            "the clock (--clock, Initial_Clock, Final_Clock) must be finite numbers");
    // Finite ends can still be too far apart for a double (-1e308:1e308).
    if (!std::isfinite(a.clock_delta()) || !std::isfinite(a.time_end()))
        throw std::runtime_error(
            "the clock's range (--clock, Initial_Clock, Final_Clock) overflows "
            "the doubles");
    return r;
}

int run_reporting_errors(std::ostream& err, const std::function<int()>& body) {
    try {
        return body();
    } catch (const language::SceneError& e) {
        err << e.formatted();
        return 1;
    } catch (const std::bad_alloc&) {
        // A stage that does not name itself (app/out_of_memory.hpp).
        err << "hexant: error: out of memory (std::bad_alloc)\n";
        return 1;
    } catch (const std::exception& e) {
        err << "hexant: error: " << e.what() << "\n";
        return 1;
    }
}

}  // namespace hexant::app
