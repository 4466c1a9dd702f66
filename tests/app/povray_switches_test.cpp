// POV-Ray 3.7's command line in hexant: each switch resolves to what its
// .ini option resolves to (the scene's options and the render's flags),
// refusals name the switch and its place, switches and .ini files apply in
// order with hexant's flags last, frames are named as POV-Ray names them,
// and `hexant +Iscene.pov ... +KFF4 +Oa.png` renders four frames. The
// names and subsets below were checked against povray 3.7.0.10 (Debian).
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include <catch2/catch.hpp>

#include "app/command_line.hpp"
#include "app/povray_render_options.hpp"
#include "app/povray_words.hpp"
#include "app/render_command.hpp"
#include "image/image_format.hpp"

namespace fs = std::filesystem;
using hexant::app::RenderArguments;
using hexant::app::ResolvedScene;

namespace {

// A folder of the test case's own (ctest runs cases as parallel processes).
fs::path folder_for_test() {
    std::string name = Catch::getResultCapture().getCurrentTestName();
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    const fs::path folder = fs::temp_directory_path() / "hexant_povray_switches_test" / name;
    fs::remove_all(folder);
    fs::create_directories(folder);
    std::ofstream(folder / "scene.pov")
        << "camera { location <0, 0, -5> look_at 0 }\nlight_source { <0, 5, -5>, rgb 1 }\n"
           "sphere { <clock, 0, 0>, 1 pigment { rgb 1 } }\n";
    return folder;
}

std::vector<std::string> split(const std::string& words) {
    std::vector<std::string> out;
    std::istringstream in(words);
    std::string word;
    while (in >> word) out.push_back(word);
    hexant::app::mark_minus_switches(out);  // (as main does)
    return out;
}

struct Resolved {
    ResolvedScene scene;
    RenderArguments render;
    std::vector<std::string> notes;
};

Resolved resolved(const std::vector<std::string>& words, RenderArguments given = {}) {
    given.scene.files = words;
    Resolved r{hexant::app::resolve(given.scene), {}, {}};
    r.render = hexant::app::with_povray_options(given, r.scene, r.notes);
    return r;
}

// What a command line resolves to: the scene's options, the render's
// flags, and the notes with each option's source (which says where it was
// given, and so differs) left out.
std::string describe(const Resolved& r) {
    std::ostringstream s;
    const auto& o = r.scene.options;
    const auto& a = o.animation;
    s << "scene " << r.scene.scene.string() << "\nsize " << a.width << "x" << a.height
      << "\nframes " << a.initial_frame << ".." << a.final_frame << " clock " << a.initial_clock
      << ".." << a.final_clock << " cyclic " << a.cyclic << " clock_given " << a.clock_given
      << " shutter " << a.shutter << "\nat_clock "
      << (r.scene.at_clock ? std::to_string(*r.scene.at_clock) : "-") << "\nversion "
      << (o.language_version ? std::to_string(*o.language_version) : "-") << "\n";
    for (const auto& path : o.include_paths) s << "library " << path.string() << "\n";
    for (const auto& [name, value] : o.declares) s << "declare " << name << "=" << value << "\n";
    const auto& f = r.render;
    s << "output " << f.output.value_or("-") << "\nframes " << f.frames.value_or("-") << "\nresume "
      << f.resume << "\nthreads " << (f.threads ? std::to_string(*f.threads) : "-") << "\nspp "
      << (f.samples_per_pixel ? std::to_string(*f.samples_per_pixel) : "-") << "\ntarget "
      << (f.target_error ? std::to_string(*f.target_error) : "-") << "\nno_jitter " << f.no_jitter
      << "\n";
    std::vector<std::string> sources = hexant::language::render_only_sources(r.scene.povray);
    for (const auto* given : {&r.scene.povray.clock, &r.scene.povray.version})
        if (*given) sources.push_back((*given)->source);
    std::sort(sources.begin(), sources.end(),
              [](const auto& x, const auto& y) { return x.size() > y.size(); });
    for (std::string note : r.notes) {
        for (const auto& source : sources)
            for (auto at = note.find(source); at != std::string::npos; at = note.find(source))
                note.replace(at, source.size(), "SOURCE");
        s << "note " << note << "\n";
    }
    return s.str();
}

}  // namespace

TEST_CASE("each POV-Ray switch resolves as its .ini option does", "[app][povray][ini]") {
    const fs::path folder = folder_for_test();
    const std::string d = folder.string();
    const std::string scene = (folder / "scene.pov").string();
    struct Pair {
        std::string switches, ini;
        bool changes;  // from the line without either
    };
    const Pair pairs[] = {
        {"+I" + d + "/scene.pov", "Input_File_Name=scene.pov", false},
        {"+O" + d + "/a.png", "Output_File_Name=a.png", true},
        {"+O" + d + "/", "Output_File_Name=" + d + "/", true},
        {"+W64", "Width=64", true},
        {"+H48", "Height=48", true},
        {"+K0.25", "Clock=0.25", true},
        {"+KI0.5", "Initial_Clock=0.5", true},
        {"+KF2", "Final_Clock=2", true},
        {"+KFI2", "Initial_Frame=2", true},
        {"+KFF60", "Final_Frame=60", true},
        {"+SF3", "Subset_Start_Frame=3", true},
        {"+SF0.5", "Subset_Start_Frame=0.5", true},
        {"+EF7", "Subset_End_Frame=7", true},
        {"+EF0.75", "Subset_End_Frame=0.75", true},
        {"+STP2", "Frame_Step=2", true},
        {"+KC", "Cyclic_Animation=on", true},
        {"-KC", "Cyclic_Animation=off", false},
        {"+L" + d + "/lib", "Library_Path=lib", true},
        {"+D", "Display=on", true},
        {"-D", "Display=off", false},
        {"+A", "Antialias=on", true},
        {"-A", "Antialias=off", true},
        {"+A0.1", "Antialias=on\nAntialias_Threshold=0.1", true},
        {"-A0.1", "Antialias=off\nAntialias_Threshold=0.1", true},
        {"+A0.0", "Antialias=on\nAntialias_Threshold=0", true},
        {"+A +AM2", "Antialias=on\nSampling_Method=2", true},
        {"+A +AM0", "Antialias=on\nSampling_Method=0", true},
        {"+A +R4", "Antialias=on\nAntialias_Depth=4", true},
        {"+A +R12", "Antialias=on\nAntialias_Depth=12", true},
        {"+A -J", "Antialias=on\nJitter=off", true},
        {"+A +J0.5", "Antialias=on\nJitter=on\nJitter_Amount=0.5", true},
        {"+A +J0", "Antialias=on\nJitter=on\nJitter_Amount=0", true},
        {"+AM2", "Sampling_Method=2", true},
        {"+R2", "Antialias_Depth=2", true},
        {"-J", "Jitter=off", true},
        {"+F", "Output_To_File=on", false},
        {"+FN", "Output_File_Type=N", true},
        {"+FE", "Output_File_Type=E", true},
        {"+FN8", "Output_File_Type=N\nBits_Per_Color=8", true},
        {"+FN5", "Output_File_Type=N\nBits_Per_Colour=5", true},
        {"+FE +O" + d + "/f.png", "Output_File_Type=E\nOutput_File_Name=f.png", true},
        {"+C", "Continue_Trace=on", true},
        {"-C", "Continue_Trace=off", false},
        {"+Q5", "Quality=5", true},
        {"+Q9", "Quality=9", false},
        {"+MV3.5", "Version=3.5", true},
        {"+WT3", "Work_Threads=3", true},
        // Key=Value on the command line is the option itself.
        {"Declare=Speed=2", "Declare=Speed=2", true},
        {"Antialias=on Antialias_Threshold=0.2", "Antialias=on\nAntialias_Threshold=0.2", true},
    };
    // An animation, so that the subsets, the clock and the names matter.
    const std::string nothing = describe(resolved({scene, "+KFF10"}));
    for (const auto& [switches, text, changes] : pairs) {
        INFO(switches << " against an .ini holding\n" << text);
        std::ofstream(folder / "options.ini") << text << "\n";
        std::vector<std::string> by_switch = split(switches);
        std::vector<std::string> by_ini{(folder / "options.ini").string()};
        if (switches.rfind("+I", 0) != 0) {
            by_switch.insert(by_switch.begin(), scene);
            by_ini.insert(by_ini.begin(), scene);
        }
        by_switch.insert(by_switch.begin() + 1, "+KFF10");
        by_ini.insert(by_ini.begin() + (by_ini.size() == 1 ? 0 : 1), "+KFF10");
        const std::string described = describe(resolved(by_switch));
        CHECK(described == describe(resolved(by_ini)));
        CHECK((described != nothing) == changes);
    }
}

TEST_CASE("the POV-Ray switches map onto render's sampling as the notes say",
          "[app][povray][sampling]") {
    const fs::path folder = folder_for_test();
    const std::string scene = (folder / "scene.pov").string();
    // -A: one ray through each pixel's centre at the frame's clock.
    auto r = resolved({scene, "+KFF2"});
    auto off = resolved(split(scene + " +KFF2 -A"));
    CHECK(off.render.samples_per_pixel == 1);
    CHECK(off.render.no_jitter);
    CHECK(off.scene.options.animation.shutter == 0.0);
    CHECK(off.render.scene.shutter == 0.0);  // (over a scene's motion_blur too)
    REQUIRE(off.notes.size() == 1);
    CHECK(off.notes[0].find("-A: one ray through each pixel's centre") == 0);
    RenderArguments shutter;
    shutter.scene.shutter = 0.5;
    auto half = resolved(split(scene + " +KFF2 -A"), shutter);
    CHECK(half.scene.options.animation.shutter == 0.5);
    CHECK(half.notes[0].find("the middle of the --shutter given") != std::string::npos);
    // +A0.3 (POV-Ray's default threshold) is hexant's default target.
    auto on = resolved({scene, "+KFF2", "+A0.3"});
    CHECK(on.render.target_error == Approx(hexant::app::kDefaultTargetError));
    CHECK_FALSE(on.render.samples_per_pixel);
    // A lower threshold asks for less error; a greater depth a higher ceiling.
    auto fine = resolved({scene, "+KFF2", "+A0.1", "+R4"});
    CHECK(fine.render.target_error == Approx(hexant::app::kDefaultTargetError / 3));
    CHECK(fine.render.samples_per_pixel == 456);  // 256 x 16 / 9, even
    CHECK(fine.notes.back().find("--target-error") != std::string::npos);
    // The hexant flags win over the switches.
    RenderArguments flags;
    flags.samples_per_pixel = 16;
    auto both = resolved({scene, "+KFF2", "+A0.1", "+R4"}, flags);
    CHECK(both.render.samples_per_pixel == 16);
    CHECK(both.notes.back().find("--spp as given wins") != std::string::npos);
    // Without +R the note names the --spp given as the ceiling, not the
    // default 256 the render will not take (a user found it so).
    auto ceiling = resolved({scene, "+KFF2", "+A0.1"}, flags);
    CHECK(ceiling.notes.back().find("under --spp 16 (as given)") != std::string::npos);
    CHECK(ceiling.notes.back().find("256") == std::string::npos);
    // Jitter without +A shapes nothing; the note says what the render
    // takes instead: the default, or the flags given.
    auto unused = resolved({scene, "+KFF2", "Jitter=off"});
    CHECK(unused.notes.back().find("as by default (adaptively") != std::string::npos);
    auto flagged = resolved({scene, "+KFF2", "Jitter=off"}, flags);
    CHECK(flagged.notes.back().find("as its flags say") != std::string::npos);
    // A single --spp cannot be adaptive: a fixed count, the switch's
    // target dropped (POV-Ray's camera2.ini has Antialias=On; with --spp 1
    // the render was refused). An odd count of 2 or more estimates its
    // error from its blocks as any other: adaptive, that the ceiling.
    hexant::runtime::SceneDescription description;
    RenderArguments single;
    single.samples_per_pixel = 1;
    auto one = resolved({scene, "+KFF2", "+A0.2"}, single);
    CHECK(one.render.samples_per_pixel == 1);
    CHECK_FALSE(one.render.target_error);
    CHECK(one.notes.back().find("not adaptive") != std::string::npos);
    CHECK_NOTHROW(hexant::app::resolve_sampling(one.render, description));
    RenderArguments odd;
    odd.samples_per_pixel = 3;
    auto three = resolved({scene, "+KFF2", "+A0.2"}, odd);
    CHECK(three.render.samples_per_pixel == 3);
    CHECK(three.render.target_error);
    CHECK_NOTHROW(hexant::app::resolve_sampling(three.render, description));
    // The resolved sampling is one render takes.
    const auto sampling = hexant::app::resolve_sampling(fine.render, description);
    CHECK(sampling.samples == 456);
    CHECK(sampling.target_error == Approx(hexant::app::kDefaultTargetError / 3));
    CHECK(r.notes.empty());
}

TEST_CASE("switches and .ini files apply in order, hexant's flags after them", "[app][povray]") {
    const fs::path folder = folder_for_test();
    const std::string scene = (folder / "scene.pov").string();
    std::ofstream(folder / "size.ini") << "Width=200\nHeight=100\n+A0.2\n";
    const std::string ini = (folder / "size.ini").string();
    auto size = [&](const std::vector<std::string>& words, RenderArguments given = {}) {
        const auto r = resolved(words, given);
        return std::to_string(r.scene.options.animation.width) + "x" +
               std::to_string(r.scene.options.animation.height);
    };
    CHECK(size({scene, "+W100", ini}) == "200x100");
    CHECK(size({scene, ini, "+W300"}) == "300x100");
    CHECK(size({scene, "Width=50", ini, "+W300", "Height=20"}) == "300x20");
    RenderArguments flags;
    flags.scene.width = 64;
    CHECK(size({scene, ini, "+W300"}, flags) == "64x100");
    // -A after the .ini's +A0.2 turns antialiasing off again.
    CHECK(resolved(split(scene + " " + ini + " -A")).render.samples_per_pixel == 1);
    CHECK_FALSE(resolved(split(scene + " -A " + ini)).render.samples_per_pixel);
    // +K is a still's clock; --clock wins over it.
    CHECK(resolved({scene, "+K0.25"}).scene.options.animation.initial_clock == 0.25);
    RenderArguments clock;
    clock.scene.clock_range = "0.5";
    CHECK(resolved({scene, "+K0.25"}, clock).scene.options.animation.initial_clock == 0.5);
    // The scene named twice, as a word and by +I: which one is meant?
    REQUIRE_THROWS_WITH(
        resolved({scene, "+Iother.pov"}),
        Catch::Contains("more than one scene named") && Catch::Contains("+Iother.pov"));
    // -o wins over +O, --frames over +SF, with a note each.
    RenderArguments output;
    output.output = (folder / "x_####.png").string();
    output.frames = "2:3";
    const auto over = resolved({scene, "+KFF4", "+Oa.png", "+SF3"}, output);
    CHECK(over.render.output == output.output);
    CHECK(over.render.frames == "2:3");
    REQUIRE(over.notes.size() == 2);
    CHECK(over.notes[0] == "+Oa.png: overridden by -o");
    CHECK(over.notes[1] == "+SF3: overridden by --frames");
}

TEST_CASE("refused switches and options are errors naming them and their place", "[app][povray]") {
    const fs::path folder = folder_for_test();
    const std::string scene = (folder / "scene.pov").string();
    const auto error = [&](const std::vector<std::string>& words) {
        RenderArguments a;
        a.scene.files = words;
        std::ostringstream out, err;
        CHECK(hexant::app::run_render(a, out, err) == 1);
        return err.str();
    };
    const std::pair<std::string, std::string> refused[] = {
        {"+FJ", "+FJ: hexant does not write frames as JPEG"},
        {"+FS", "+FS: POV-Ray 3.7 on Unix has no system output format"},
        {"+FN17", "+FN17: POV-Ray writes 5 to 16 bits per colour, not 17"},
        {"+FNg", "+FNg: hexant writes colour frames only"},
        {"-F", "-F: hexant writes every frame to a file"},
        {"-FN", "-FN: hexant writes every frame to a file"},
        {"+O-", "+O-: hexant writes frames to files, not to a stream"},
        {"+EF20", "+EF20: frame 20 lies past the animation's last, frame 10"},
        {"+SF11", "+SF11: frame 11 lies past the animation's last, frame 10"},
        {"+STP0", "+STP0: the step must be 1 or more"},
        {"+WT0", "+WT0: needs 1 thread or more"},
        {"+ZZ", "+ZZ: not a POV-Ray 3.7 switch"},
        {"+A1.0", "+A1.0: not a POV-Ray 3.7 switch"},
        {"+W", "+W: not a POV-Ray 3.7 switch"},
        {"+Wabc", "+Wabc needs a whole number, not 'abc'"},
        {"-KFFten", "-KFFten needs a whole number, not 'ten'"},
    };
    for (const auto& [word, message] : refused) {
        INFO(word);
        CHECK_THAT(error(split(scene + " +KFF10 " + word)),
                   Catch::StartsWith("hexant: error: " + message));
    }
    // The same in an .ini file: its name and line first.
    const std::pair<std::string, std::string> in_ini[] = {
        {"Output_File_Type=J", "Output_File_Type=J: hexant does not write frames as JPEG"},
        {"Output_File_Type=X", "Output_File_Type=X: 'X' is not a POV-Ray output type"},
        {"Bits_Per_Color=20", "Bits_Per_Color=20: POV-Ray writes 5 to 16 bits per colour"},
        {"Output_To_File=off", "Output_To_File=off: hexant writes every frame to a file"},
        {"Subset_End_Frame=20", "Subset_End_Frame=20: frame 20 lies past"},
        {"Frame_Step=0", "Frame_Step=0: the step must be 1 or more"},
        {"Work_Threads=0", "Work_Threads=0: needs 1 thread or more"},
        {"Output_File_Name=../a.png", "Output_File_Name=../a.png: outside the .ini file's folder"},
        {"+FJ", "+FJ: hexant does not write frames as JPEG"},
        {"Width=abc", "Width needs a whole number, not 'abc'"},
    };
    const fs::path ini = folder / "bad.ini";
    for (const auto& [line, message] : in_ini) {
        INFO(line);
        std::ofstream(ini) << "Final_Frame=10\n" << line << "\n";
        CHECK_THAT(error({scene, ini.string()}),
                   Catch::StartsWith("hexant: error: " + ini.string() + ":2: " + message));
    }
}

TEST_CASE("frames are named as POV-Ray 3.7 names them", "[app][povray][output]") {
    using hexant::app::povray_frame_pattern;
    hexant::runtime::Animation a;
    a.final_frame = 4;
    const fs::path scene = "dir/s.pov";
    // The number's digits are the last frame's, before the extension.
    CHECK(povray_frame_pattern("out/a.png", ".png", a, scene) == "out/a#.png");
    CHECK(povray_frame_pattern("out/d.tga", ".png", a, scene) == "out/d.tga#.png");
    CHECK(povray_frame_pattern("out/e.PNG", ".png", a, scene) == "out/e.PNG#.png");
    CHECK(povray_frame_pattern("out/f.png", ".exr", a, scene) == "out/f.png#.exr");
    CHECK(povray_frame_pattern("out/x.", ".png", a, scene) == "out/x#.png");
    CHECK(povray_frame_pattern("out/", ".png", a, scene) == "out/s#.png");
    CHECK(povray_frame_pattern(".png", ".png", a, scene) == "s#.png");
    CHECK(povray_frame_pattern("out/h_####.png", ".png", a, scene) == "out/h_####.png");
    a.final_frame = 12;
    CHECK(povray_frame_pattern("out/b", ".png", a, scene) == "out/b##.png");
    a.final_frame = 9;
    a.cyclic = true;  // counted as 10 frames: m01 to m09
    CHECK(povray_frame_pattern("out/m", ".png", a, scene) == "out/m##.png");
    a.final_frame = a.initial_frame;
    a.cyclic = false;  // a still: no number
    CHECK(povray_frame_pattern("out/g.png", ".png", a, scene) == "out/g.png");
}

TEST_CASE("the subset of frames is POV-Ray's", "[app][povray][frames]") {
    using hexant::app::povray_frames;
    hexant::runtime::Animation a;
    a.final_frame = 12;
    const auto frames = [&](const std::string& words) {
        hexant::language::PovRaySettings s;
        std::istringstream in(words);
        std::string word;
        while (in >> word) hexant::language::apply_povray_switch(word, "", "", s);
        return povray_frames(s, a).value_or("all");
    };
    CHECK(frames("") == "all");
    CHECK(frames("+SF3 +EF7") == "3:7");
    CHECK(frames("+SF0.5") == "6:12");    // half of 12 frames
    CHECK(frames("+EF0.25") == "1:3");    // (fractions from 0, not from the first)
    CHECK(frames("+EF1.0") == "1:1");     // 1.0 is frame 1, not all (as POV-Ray)
    CHECK(frames("+SF5 +EF2") == "5:5");  // the end no earlier than the start
    CHECK(frames("+STP5") == "1,6,11");   // a step
    CHECK(frames("+SF2 +STP4") == "2,6,10");
    a.cyclic = true;                    // 13 frames as POV-Ray counts them
    CHECK(frames("+SF0.5") == "6:12");  // int(13 x 0.5)
    a.cyclic = false;
    a.initial_frame = 5;
    CHECK(frames("+SF0.1") == "5:12");  // no earlier than the first
}

TEST_CASE("POV-Ray's words reach the subcommands: - switches, no subcommand",
          "[app][povray][command-line]") {
    const auto words = [](std::vector<const char*> argv) {
        argv.insert(argv.begin(), "hexant");
        std::vector<std::string> out =
            hexant::app::command_line_words(int(argv.size()), argv.data());
        for (auto& word : out)
            if (const auto minus = hexant::app::minus_switch(word)) word = "<" + *minus + ">";
        std::string joined;
        for (const auto& word : out) joined += (joined.empty() ? "" : " ") + word;
        return joined;
    };
    CHECK(words({"scene.pov", "+W64"}) == "render scene.pov +W64");
    CHECK(words({"res.INI[High]"}) == "render res.INI[High]");
    CHECK(words({"+Iscene.pov", "-D"}) == "render +Iscene.pov <-D>");
    CHECK(words({"-D", "scene.pov"}) == "render <-D> scene.pov");
    CHECK(words({"Width=64", "scene.pov"}) == "render Width=64 scene.pov");
    // hexant's own short flags keep their meaning; -WT2 and -w64 are POV-Ray's.
    CHECK(words({"check", "a.pov", "-W", "64", "-H48", "-WT2", "-w64", "-KC", "-o", "x", "-Llib",
                 "-h"}) == "check a.pov -W 64 -H48 <-WT2> <-w64> <-KC> -o x -Llib -h");
    // Not a switch: left to CLI11, which says so.
    CHECK(words({"render", "a.pov", "-Z", "--frames", "1:2"}) == "render a.pov -Z --frames 1:2");
    CHECK(words({"bench", "error-time", "a.pov", "-A"}) == "bench error-time a.pov <-A>");
    // Other subcommands, and no subcommand at all, as they were.
    CHECK(words({"farm", "a.pov", "-D"}) == "farm a.pov -D");
    CHECK(words({"--help"}) == "--help");
    CHECK(words({"nonsense"}) == "nonsense");
    CHECK(words({}).empty());
}

TEST_CASE("hexant +Iscene.pov +W64 +H48 +KFF4 +Oout/a.png renders four frames",
          "[app][povray][binary]") {
    const fs::path folder = folder_for_test();
    const std::string hexant = HEXANT_BINARY;
    const std::string atom = std::string(HEXANT_SOURCE_DIR) + "/examples/atom.pov";
    const fs::path out = folder / "out";
    const std::string command = hexant + " +I" + atom + " +W64 +H48 +KFF4 +O" +
                                (out / "a.png").string() + " -D > " + (folder / "log").string() +
                                " 2>&1";
    REQUIRE(std::system(command.c_str()) == 0);
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(out))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    // (.hexant: the frames' records, app/frame_record.hpp.)
    CHECK(names == std::vector<std::string>{".hexant", "a1.png", "a2.png", "a3.png", "a4.png"});
    for (const auto& name : names) {
        if (name == ".hexant") continue;
        const auto image = hexant::image::read_stored_image(out / name, 64 * 48);
        CHECK(image.width == 64);
        CHECK(image.height == 48);
    }
    // A refused switch: a non-zero exit, the switch named.
    const std::string refused =
        hexant + " " + atom + " +W64 +H48 +FJ > " + (folder / "refused").string() + " 2>&1";
    CHECK(std::system(refused.c_str()) != 0);
    std::ifstream said(folder / "refused");
    const std::string text((std::istreambuf_iterator<char>(said)), {});
    CHECK_THAT(text, Catch::Contains("+FJ: hexant does not write frames as JPEG"));
}
