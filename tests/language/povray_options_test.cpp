// POV-Ray 3.7's options table: how switches are matched (as POV-Ray's own
// table matches them), that each switch sets what its .ini option sets,
// and that what hexant cannot do is refused naming the switch and place.
// The matching rules were checked against povray 3.7.0.10 (Debian): +A0
// and +A1.0 are unknown switches there, +KFF4 +KF1.5 +K0.5 are three.
#include "language/povray_options.hpp"

#include <sstream>

#include <catch2/catch.hpp>

#include "language/ini_file.hpp"
#include "language/interpreter.hpp"

namespace fs = std::filesystem;
using hexant::language::apply_povray_switch;
using hexant::language::PovRaySettings;

namespace {

PovRaySettings switches(const std::string& words) {
    PovRaySettings s;
    std::istringstream in(words);
    std::string word;
    while (in >> word)
        if (!apply_povray_switch(word, "", "", s)) throw std::runtime_error("no switch: " + word);
    return s;
}

PovRaySettings ini(const std::string& text) {
    return hexant::language::parse_ini_text(text, "test.ini", "", {});
}

// Every value the settings hold, without where each was given.
std::string values(const PovRaySettings& s) {
    std::ostringstream out;
    const auto put = [&](const char* name, const auto& field) {
        out << name << "=";
        if (field) out << *field;
        out << ";";
    };
    const auto given = [&](const char* name, const auto& field) {
        out << name << "=";
        if (field) out << field->value;
        out << ";";
    };
    out << "input=" << (s.input_file ? s.input_file->string() : "") << ";";
    put("width", s.width);
    put("height", s.height);
    put("initial_frame", s.initial_frame);
    put("final_frame", s.final_frame);
    put("initial_clock", s.initial_clock);
    put("final_clock", s.final_clock);
    put("cyclic", s.cyclic);
    for (const auto& path : s.library_paths) out << "library=" << path.string() << ";";
    for (const auto& [name, value] : s.declares) out << "declare=" << name << "=" << value << ";";
    given("clock", s.clock);
    given("version", s.version);
    out << "output=" << (s.output_file ? s.output_file->value.string() : "") << ";";
    given("output_to_file", s.output_to_file);
    given("type", s.output_type);
    given("bits", s.bits_per_colour);
    given("subset_start", s.subset_start);
    given("subset_end", s.subset_end);
    given("step", s.frame_step);
    given("antialias", s.antialias);
    given("threshold", s.antialias_threshold);
    given("method", s.sampling_method);
    given("depth", s.antialias_depth);
    given("jitter", s.jitter);
    given("jitter_amount", s.jitter_amount);
    given("continue", s.continue_trace);
    given("quality", s.quality);
    given("display", s.display);
    given("threads", s.work_threads);
    out << "warnings=" << s.warnings.size();
    return out.str();
}

}  // namespace

TEST_CASE("povray switches: matched as POV-Ray 3.7 matches them", "[language][povray]") {
    // The first entry whose letters begin the word and that takes a value
    // exactly when one follows.
    const auto k = switches("+KFF4 +KF1.5 +K0.5 +KI0.25 +KFI2");
    CHECK(k.final_frame == 4);
    CHECK(k.final_clock == 1.5);
    CHECK(k.clock->value == 0.5);
    CHECK(k.initial_clock == 0.25);
    CHECK(k.initial_frame == 2);
    CHECK(switches("+kc").cyclic == true);  // in any case
    CHECK(switches("-KC").cyclic == false);
    // +A0.3: antialiasing on, threshold 0.3; the sign turns it on or off.
    const auto a = switches("+A0.3");
    CHECK(a.antialias->value);
    CHECK(a.antialias_threshold->value == 0.3);
    CHECK(a.antialias_threshold->source == "+A0.3");
    CHECK_FALSE(switches("-A0.2").antialias->value);
    CHECK(switches("-A0.2").antialias_threshold->value == 0.2);
    CHECK(switches("+A").antialias->value);
    CHECK_FALSE(switches("+A").antialias_threshold);
    PovRaySettings none;
    CHECK_FALSE(apply_povray_switch("+A0", "", "", none));    // POV-Ray: unknown
    CHECK_FALSE(apply_povray_switch("+A1.0", "", "", none));  // the threshold begins with 0
    CHECK_FALSE(apply_povray_switch("+W", "", "", none));     // W takes a number
    CHECK_FALSE(apply_povray_switch("+ZZ", "", "", none));
    CHECK_FALSE(apply_povray_switch("W64", "", "", none));  // no sign: no switch
    // Fractions and frame numbers of the subset; WT is not W.
    CHECK(switches("+SF0.5").subset_start->value == 0.5);
    CHECK(switches("+SF3").subset_start->value == 3.0);
    CHECK(switches("+EF0.25").subset_end->value == 0.25);
    const auto threads = switches("+WT4");
    CHECK(threads.work_threads->value == 4);
    CHECK_FALSE(threads.width);
    // +Fx sets the type, and its bits; the sign turns file output on or off.
    const auto f = switches("+FN16");
    CHECK(f.output_type->value == 'N');
    CHECK(f.bits_per_colour->value == 16);
    CHECK(f.output_to_file->value);
    CHECK(switches("+fe").output_type->value == 'E');
    CHECK_FALSE(switches("-F").output_to_file->value);
    // +D0T: display on (its video mode and palette are nothing to hexant).
    CHECK(switches("+D0T").display->value);
    CHECK_FALSE(switches("-D").display->value);
    const auto j = switches("+J0.5");
    CHECK(j.jitter->value);
    CHECK(j.jitter_amount->value == 0.5);
    CHECK(switches("+MV3.5").version->value == 3.5);
    CHECK(switches("+Q5").quality->value == 5);
    CHECK(switches("+C").continue_trace->value);
    CHECK_FALSE(switches("-C").continue_trace->value);
    CHECK(switches("+STP3").frame_step->value == 3);
    CHECK(switches("+Oout/a.png").output_file->value == fs::path("out/a.png"));
    // A POV-Ray switch hexant has no use for: a warning naming it.
    const auto ignored = switches("+UA +HR");
    REQUIRE(ignored.warnings.size() == 2);
    CHECK(ignored.warnings[0] == "command line: switch '+UA' is ignored");
}

TEST_CASE("povray switches: each sets what its .ini option sets", "[language][povray][ini]") {
    const std::pair<const char*, const char*> pairs[] = {
        {"+Iscene.pov", "Input_File_Name=scene.pov"},
        {"+Oa.png", "Output_File_Name=a.png"},
        {"+W64", "Width=64"},
        {"+H48", "Height=48"},
        {"+K0.25", "Clock=0.25"},
        {"+KI0.5", "Initial_Clock=0.5"},
        {"+KF2", "Final_Clock=2"},
        {"+KFI2", "Initial_Frame=2"},
        {"+KFF60", "Final_Frame=60"},
        {"+SF3", "Subset_Start_Frame=3"},
        {"+SF0.5", "Subset_Start_Frame=0.5"},
        {"+EF7", "Subset_End_Frame=7"},
        {"+EF0.75", "Subset_End_Frame=0.75"},
        {"+STP2", "Frame_Step=2"},
        {"+KC", "Cyclic_Animation=on"},
        {"-KC", "Cyclic_Animation=off"},
        {"+Llib", "Library_Path=lib"},
        {"+D", "Display=on"},
        {"-D", "Display=off"},
        {"+A", "Antialias=on"},
        {"-A", "Antialias=off"},
        {"+A0.1", "Antialias=on\nAntialias_Threshold=0.1"},
        {"-A0.1", "Antialias=off\nAntialias_Threshold=0.1"},
        {"+AM2", "Sampling_Method=2"},
        {"+R4", "Antialias_Depth=4"},
        {"+J", "Jitter=on"},
        {"-J", "Jitter=off"},
        {"+J0.5", "Jitter=on\nJitter_Amount=0.5"},
        {"+F", "Output_To_File=on"},
        {"-F", "Output_To_File=off"},
        {"+FN", "Output_To_File=on\nOutput_File_Type=N"},
        {"+FE", "Output_To_File=on\nOutput_File_Type=E"},
        {"+FN8", "Output_To_File=on\nOutput_File_Type=N\nBits_Per_Color=8"},
        {"+C", "Continue_Trace=on"},
        {"-C", "Continue_Trace=off"},
        {"+Q5", "Quality=5"},
        {"+MV3.5", "Version=3.5"},
        {"+WT4", "Work_Threads=4"},
    };
    const std::string nothing = values(PovRaySettings{});
    for (const auto& [words, text] : pairs) {
        INFO(words << " against " << text);
        const std::string by_switch = values(switches(words));
        CHECK(by_switch == values(ini(text)));
        CHECK(by_switch != nothing);  // (each sets something)
    }
    // The switch's own line in an .ini means the same too.
    CHECK(values(ini("+A0.1 +R4\n")) == values(ini("Antialias=on\nAntialias_Threshold=0.1\n"
                                                   "Antialias_Depth=4\n")));
}

TEST_CASE("povray switches: what hexant cannot write is refused, naming the switch",
          "[language][povray]") {
    // JPEG is lossy (a frame must read back as written); +FS is no Unix
    // POV-Ray's.
    for (const char* type : {"+FJ", "-FJ", "+FS"}) {
        INFO(type);
        REQUIRE_THROWS_WITH(switches(type),
                            Catch::StartsWith(std::string(type) + ": ") && Catch::Contains("+FN"));
    }
    REQUIRE_THROWS_WITH(switches("+FJ"), Catch::Contains("lossy"));
    // The others set their type.
    for (const char* type : {"+FT", "+FC", "+FP", "+FB", "+FH", "+FN", "+FE"})
        CHECK(switches(type).output_type->value == type[2]);
    REQUIRE_THROWS_WITH(switches("+FX"),
                        Catch::StartsWith("+FX: 'X' is not a POV-Ray output type"));
    REQUIRE_THROWS_WITH(switches("+FNg"), Catch::StartsWith("+FNg: hexant writes colour frames"));
    REQUIRE_THROWS_WITH(switches("+FN1x"), Catch::StartsWith("+FN1x needs"));
    REQUIRE_THROWS_WITH(switches("+Wabc"), "+Wabc needs a whole number, not 'abc'");
    REQUIRE_THROWS_WITH(switches("+KF1x"), Catch::StartsWith("+KF1x needs a number"));
    // In an .ini file: the file, the line and the option.
    REQUIRE_THROWS_WITH(ini("Width=64\nOutput_File_Type=J\n"),
                        Catch::StartsWith("test.ini:2: Output_File_Type=J: hexant does not write "
                                          "frames as JPEG"));
    REQUIRE_THROWS_WITH(ini("Output_File_Type=N16\n"),
                        Catch::StartsWith("test.ini:1: Output_File_Type needs one letter"));
    REQUIRE_THROWS_WITH(ini("\n+FJ\n"), Catch::StartsWith("test.ini:2: +FJ: "));
    REQUIRE_THROWS_WITH(ini("Antialias=maybe\n"),
                        "test.ini:1: Antialias needs on or off, not 'maybe'");
}

TEST_CASE("povray options: an .ini names the frames' files in its own folder only",
          "[language][povray][ini][confinement]") {
    // As its Library_Path (issue 45): a downloaded scene's .ini may not
    // choose where files are written; +O on the command line may.
    const fs::path folder = fs::temp_directory_path() / "hexant_povray_options_test";
    const auto in_folder = [&](const std::string& text) {
        return hexant::language::parse_ini_text(text, "x.ini", folder);
    };
    CHECK(in_folder("Output_File_Name=frames/a.png\n").output_file->value ==
          folder / "frames/a.png");
    REQUIRE_THROWS_WITH(in_folder("Output_File_Name=../a.png\n"),
                        Catch::StartsWith("x.ini:1: Output_File_Name=../a.png: outside the .ini "
                                          "file's folder"));
    REQUIRE_THROWS_WITH(in_folder("+O/tmp/a.png\n"), Catch::StartsWith("x.ini:1: +O/tmp/a.png"));
    CHECK(switches("+O/tmp/a.png").output_file->value == fs::path("/tmp/a.png"));
}

TEST_CASE("povray options: Version (+MV) is the language's version at the start",
          "[language][povray]") {
    // As a #version at the top: POV-Ray 3.7 sets its version, and that a
    // version was set, from +MV (Scene::StartParser).
    const auto objects = [](std::optional<double> version) {
        hexant::language::ParseOptions options;
        std::ostringstream messages;
        options.messages = &messages;
        options.language_version = version;
        const auto scene = hexant::language::parse_scene_text(
            "#if (version < 3.6) sphere { 0, 1 } #end\n#if (version = 3.5) sphere { 0, 1 } #end",
            "test.pov", options);
        return scene.objects.size();
    };
    CHECK(objects(std::nullopt) == 0);
    CHECK(objects(3.5) == 2);
    CHECK(objects(3.504) == 2);  // in hundredths, as POV-Ray keeps it
    CHECK(objects(3.6) == 0);
    hexant::language::ParseOptions options;
    std::filesystem::path scene;
    hexant::language::apply_ini_settings(ini("Version=3.5\n"), options, scene);
    CHECK(options.language_version == 3.5);
}
