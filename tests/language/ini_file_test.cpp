// POV-Ray .ini files: keys, switches, sections, bad values, and how the
// settings land on ParseOptions. The section rules were checked against
// povray 3.7 (`povray res.ini` reads only the unlabelled lines,
// `povray 'res.ini[high]'` those and the [High] section).
#include "language/ini_file.hpp"

#include <filesystem>
#include <fstream>

#include <catch2/catch.hpp>
#include <sys/stat.h>

namespace fs = std::filesystem;
using hexant::language::ini_reference;
using hexant::language::parse_ini_text;

namespace {

hexant::language::IniSettings parse(const std::string& text, const std::string& section = {}) {
    return parse_ini_text(text, "test.ini", "folder", section);
}

}  // namespace

TEST_CASE("ini: keys in any case, comments, blanks and quotes", "[language][ini]") {
    const auto s = parse(
        "; the options\n"
        "Input_File_Name = \"scene.pov\"  ; the scene\n"
        "WIDTH=126\n"
        "height=96\n"
        "Initial_Frame=1\nFinal_Frame=64\n"
        "Initial_Clock=-0.5\nFinal_Clock=2.5e0\n"
        "Cyclic_Animation=On\n"
        "Library_Path=lib\nLibrary_Path=/abs\n"
        "Declare=Speed=3\nDeclare = Name = 1 + 2\n");
    REQUIRE(s.input_file);
    CHECK(*s.input_file == fs::path("folder") / "scene.pov");
    CHECK(s.width == 126);
    CHECK(s.height == 96);
    CHECK(s.initial_frame == 1);
    CHECK(s.final_frame == 64);
    CHECK(s.initial_clock == -0.5);
    CHECK(s.final_clock == 2.5);
    CHECK(s.cyclic == true);
    REQUIRE(s.library_paths.size() == 2);
    CHECK(s.library_paths[0] == fs::path("folder") / "lib");
    CHECK(s.library_paths[1] == fs::path("/abs"));
    REQUIRE(s.declares.size() == 2);
    CHECK(s.declares[0] == std::pair<std::string, std::string>{"Speed", "3"});
    CHECK(s.declares[1] == std::pair<std::string, std::string>{"Name", "1 + 2"});
    CHECK(s.warnings.empty());
}

TEST_CASE("ini: an option not given stays empty, the last of one given twice wins",
          "[language][ini]") {
    const auto s = parse("Width=10\nWidth=20\n");
    CHECK(s.width == 20);
    CHECK_FALSE(s.height);
    CHECK_FALSE(s.input_file);
    CHECK_FALSE(s.cyclic);
    CHECK_FALSE(s.initial_clock);
}

TEST_CASE("ini: every boolean spelling", "[language][ini]") {
    for (const char* on : {"on", "TRUE", "yes", "1"})
        CHECK(parse(std::string("Cyclic_Animation=") + on).cyclic == true);
    for (const char* off : {"off", "False", "NO", "0"})
        CHECK(parse(std::string("Cyclic_Animation=") + off).cyclic == false);
}

TEST_CASE("ini: POV-Ray's switches, several on a line", "[language][ini]") {
    const auto s =
        parse("+W320 +H240 ; size\n+KFI2 +KFF9\n+KI0.5 +KF1.5\n+KC\n+Linc\n+Iscene.pov\n");
    CHECK(s.width == 320);
    CHECK(s.height == 240);
    CHECK(s.initial_frame == 2);
    CHECK(s.final_frame == 9);
    CHECK(s.initial_clock == 0.5);
    CHECK(s.final_clock == 1.5);
    CHECK(s.cyclic == true);
    REQUIRE(s.library_paths.size() == 1);
    CHECK(s.library_paths[0] == fs::path("folder") / "inc");
    CHECK(s.input_file == fs::path("folder") / "scene.pov");
    CHECK(s.warnings.empty());
    CHECK(parse("-KC\n").cyclic == false);
    CHECK(parse("+kff12\n").final_frame == 12);  // switches in any case
}

TEST_CASE("ini: switches and options hexant does not use are warnings", "[language][ini]") {
    // +WT4 (threads) is not +W; +UA (alpha) and Verbose are POV-Ray's but
    // not hexant's; +ZZ9 and No_Such_Key are no one's.
    const auto s = parse("+WT4 +UA +ZZ9\nVerbose=on\n+W64\nnot an option\nNo_Such_Key=1\n");
    CHECK(s.width == 64);
    REQUIRE(s.work_threads);
    CHECK(s.work_threads->value == 4);
    CHECK(s.work_threads->source == "test.ini:1: +WT4");
    REQUIRE(s.warnings.size() == 5);
    CHECK(s.warnings[0] == "test.ini:1: switch '+UA' is ignored");
    CHECK(s.warnings[1] == "test.ini:1: '+ZZ9' is not a POV-Ray 3.7 switch; it is ignored");
    CHECK(s.warnings[2] == "test.ini:2: option 'Verbose' is ignored");
    CHECK(s.warnings[3].rfind("test.ini:4:", 0) == 0);
    CHECK(s.warnings[4] == "test.ini:5: option 'No_Such_Key' is ignored");
}

TEST_CASE("ini: only the unlabelled lines, unless a section is selected", "[language][ini]") {
    const std::string res =
        "; RES.INI\n+W120 +H100\n[Low]\n+W80 +H60\n[High]\n+W640\n[Really High]\n+W800 +H600\n";
    const auto plain = parse(res);
    CHECK(plain.width == 120);
    CHECK(plain.height == 100);
    REQUIRE(plain.warnings.size() == 3);  // one per section not read
    CHECK(plain.warnings[0] ==
          "test.ini:3: section [Low] is read only when selected, as test.ini[Low]");
    const auto high = parse(res, "high");  // labels in any case
    CHECK(high.width == 640);
    CHECK(high.height == 100);  // the unlabelled lines are read too
    CHECK(high.warnings.empty());
    const auto really = parse(res, "Really High");  // labels may hold blanks
    CHECK(really.width == 800);
    CHECK(really.height == 600);
    REQUIRE_THROWS_WITH(parse(res, "Medium"),
                        Catch::Contains("test.ini") && Catch::Contains("[Medium]"));
}

TEST_CASE("ini: a bad value names the file, the line and the option", "[language][ini]") {
    REQUIRE_THROWS_WITH(parse("Width=126\nHeight=lots\n"),
                        "test.ini:2: Height needs a whole number, not 'lots'");
    REQUIRE_THROWS_WITH(parse("\n\nWidth=12.5\n"), Catch::StartsWith("test.ini:3: Width"));
    REQUIRE_THROWS_WITH(parse("Width=\n"), Catch::StartsWith("test.ini:1: Width"));
    REQUIRE_THROWS_WITH(parse("Final_Clock=1x\n"),
                        Catch::StartsWith("test.ini:1: Final_Clock needs a number"));
    REQUIRE_THROWS_WITH(parse("Initial_Clock=nan\n"), Catch::StartsWith("test.ini:1:"));
    REQUIRE_THROWS_WITH(parse("Cyclic_Animation=maybe\n"),
                        "test.ini:1: Cyclic_Animation needs on or off, not 'maybe'");
    REQUIRE_THROWS_WITH(parse("Declare=Speed\n"),
                        Catch::StartsWith("test.ini:1: Declare needs NAME=VALUE"));
    REQUIRE_THROWS_WITH(parse("Declare==3\n"),
                        Catch::StartsWith("test.ini:1: Declare needs NAME=VALUE"));
    REQUIRE_THROWS_WITH(parse("+W640\n+KFFten\n"),
                        Catch::StartsWith("test.ini:2: +KFFten needs a whole number"));
}

TEST_CASE("ini: which command-line words name .ini files", "[language][ini]") {
    const auto plain = ini_reference("examples/atom.ini");
    REQUIRE(plain);
    CHECK(plain->file == "examples/atom.ini");
    CHECK(plain->section.empty());
    const auto upper = ini_reference("RES.INI[High]");
    REQUIRE(upper);
    CHECK(upper->file == "RES.INI");
    CHECK(upper->section == "High");
    CHECK_FALSE(ini_reference("scene.pov"));
    CHECK_FALSE(ini_reference("scene.pov[x]"));
    CHECK_FALSE(ini_reference(".ini"));
    CHECK_FALSE(ini_reference("ini"));
}

TEST_CASE("ini: settings replace what they set, and paths and declarations append",
          "[language][ini]") {
    hexant::language::ParseOptions options;
    options.animation.width = 640;
    options.animation.final_clock = 3.0;
    options.include_paths = {"first"};
    options.declares = {{"A", "1"}};
    fs::path scene = "named.pov";
    const auto s = parse("Height=50\nFinal_Frame=8\nLibrary_Path=lib\nDeclare=B=2\n");
    hexant::language::apply_ini_settings(s, options, scene);
    CHECK(scene == "named.pov");  // no Input_File_Name: the scene stays
    CHECK(options.animation.width == 640);
    CHECK(options.animation.height == 50);
    CHECK(options.animation.final_frame == 8);
    CHECK(options.animation.final_clock == 3.0);
    CHECK(options.include_paths == std::vector<fs::path>{"first", fs::path("folder") / "lib"});
    REQUIRE(options.declares.size() == 2);
    CHECK(options.declares[1].first == "B");
    hexant::language::apply_ini_settings(parse("Input_File_Name=other.pov\n"), options, scene);
    CHECK(scene == fs::path("folder") / "other.pov");
}

TEST_CASE("ini: a file on disk, relative paths from its folder", "[language][ini]") {
    const fs::path folder = fs::temp_directory_path() / "hexant_ini_file_test";
    fs::create_directories(folder);
    const fs::path file = folder / "anim.ini";
    std::ofstream(file) << "Input_File_Name=scene.pov\r\nWidth=7\r\n";  // CRLF lines too
    const auto s = hexant::language::read_ini_file(file);
    CHECK(s.input_file == folder / "scene.pov");
    CHECK(s.width == 7);
    REQUIRE_THROWS_WITH(hexant::language::read_ini_file(folder / "missing.ini"),
                        Catch::Contains("cannot read"));
    // A FIFO named as the .ini is refused, not waited on forever (issue 45).
    fs::remove(folder / "fifo.ini");
    REQUIRE(mkfifo((folder / "fifo.ini").c_str(), 0600) == 0);
    REQUIRE_THROWS_WITH(hexant::language::read_ini_file(folder / "fifo.ini"),
                        Catch::Contains("fifo.ini") && Catch::Contains("not a regular file"));
}
