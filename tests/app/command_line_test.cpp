// The command line's shape: POV-Ray .ini files apply in order, then flags.
#include "app/command_line.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"

namespace fs = std::filesystem;

namespace {

fs::path temp_folder() {
    const fs::path folder = fs::temp_directory_path() / "hexant_command_line_test";
    fs::create_directories(folder);
    return folder;
}

fs::path write(const std::string& name, const std::string& text) {
    const fs::path path = temp_folder() / name;
    std::ofstream(path) << text;
    return path;
}

TEST_CASE("an .ini's Library_Path cannot widen what the scene reads", "[app][ini][confinement]") {
    // (issue 45) Library_Path=/etc in an .ini that came with a downloaded
    // scene made /etc readable to it. Only folders inside the scene's, or
    // allowed on the command line, are searched; the others are named.
    const auto ini = write("wide.ini",
                           "Input_File_Name=scene.pov\nLibrary_Path=/etc\nLibrary_Path=lib\n"
                           "Library_Path=../elsewhere\n");
    hexant::app::SceneArguments arguments;
    arguments.files = {ini.string()};
    auto r = hexant::app::resolve(arguments);
    REQUIRE(r.options.include_paths.size() == 1);
    CHECK(r.options.include_paths[0] == temp_folder() / "lib");
    REQUIRE(r.warnings.size() == 2);
    CHECK(r.warnings[0].find("wide.ini:2") != std::string::npos);
    CHECK(r.warnings[0].find("--allow-read /etc") != std::string::npos);
    CHECK(r.warnings[1].find("wide.ini:4") != std::string::npos);
    // --allow-read allows it, and -L folders (the user's own) stay after.
    arguments.read_paths = {"/etc"};
    arguments.include_paths = {"/usr"};
    r = hexant::app::resolve(arguments);
    REQUIRE(r.options.include_paths.size() == 3);
    CHECK(r.options.include_paths[0] == fs::path("/etc"));
    CHECK(r.options.include_paths[2] == fs::path("/usr"));
    REQUIRE(r.ini_files.size() == 1);
    CHECK(r.ini_files[0] == fs::canonical(ini));
}

// The scene arguments a command line gives (after the scene's name).
hexant::app::SceneArguments parse(const std::string& flags) {
    CLI::App app;
    hexant::app::SceneArguments arguments;
    hexant::app::add_scene_arguments(app, arguments);
    app.parse("scene.pov " + flags, false);
    return arguments;
}

auto resolved(const std::string& flags) {
    return hexant::app::resolve(parse(flags));
}

}  // namespace

TEST_CASE("an .ini file sets POV-Ray's animation options and names the scene", "[app][ini]") {
    const auto ini = write("anim.ini",
                           "; a comment\nInput_File_Name=scene.pov\nWidth=126\n"
                           "Height = 96\nInitial_Frame=1\nFinal_Frame=64\nInitial_Clock=0\n"
                           "Final_Clock=2\nCyclic_Animation=on\nLibrary_Path=lib\n"
                           "Declare=Speed=3\nVerbose=on\n");
    hexant::app::SceneArguments arguments;
    arguments.files = {ini.string()};
    const auto r = hexant::app::resolve(arguments);
    CHECK(r.scene == temp_folder() / "scene.pov");
    const auto& a = r.options.animation;
    CHECK(a.width == 126);
    CHECK(a.height == 96);
    CHECK(a.final_frame == 64);
    CHECK(a.final_clock == 2.0);
    CHECK(a.cyclic);
    CHECK(a.clock_delta() == Approx(2.0 / 64));
    REQUIRE(r.options.include_paths.size() == 1);
    CHECK(r.options.include_paths[0] == temp_folder() / "lib");
    REQUIRE(r.options.declares.size() == 1);
    CHECK(r.options.declares[0].first == "Speed");
    CHECK(r.options.declares[0].second == "3");
    REQUIRE(r.warnings.size() == 1);  // Verbose is not hexant's
    CHECK(r.warnings[0].find("anim.ini:12") != std::string::npos);
}

TEST_CASE(".ini switches and later files override earlier ones, flags override all", "[app][ini]") {
    const auto first = write("first.ini", "+W100\n+H50\n+KFI1\n+KFF10\n+KI0\n+KF1\n");
    const auto second = write("second.ini", "Width=200\n-KC\n");
    hexant::app::SceneArguments arguments;
    arguments.files = {"scene.pov", first.string(), second.string()};
    arguments.height = 77;
    arguments.frame_count = 4;
    arguments.shutter = 0.5;
    arguments.clock_range = "0.5:1.5";
    const auto r = hexant::app::resolve(arguments);
    const auto& a = r.options.animation;
    CHECK(r.scene == "scene.pov");
    CHECK(a.width == 200);
    CHECK(a.height == 77);
    CHECK(a.initial_frame == 1);
    CHECK(a.final_frame == 4);
    CHECK_FALSE(a.cyclic);
    CHECK(a.shutter == 0.5);
    CHECK(a.initial_clock == 0.5);
    CHECK(a.final_clock == 1.5);
}

TEST_CASE("a single --clock value is POV-Ray's +K for a still", "[app][ini]") {
    hexant::app::SceneArguments arguments;
    arguments.files = {"scene.pov"};
    arguments.clock_range = "0.25";
    const auto r = hexant::app::resolve(arguments);
    REQUIRE(r.at_clock);
    CHECK(*r.at_clock == 0.25);
    CHECK(r.options.animation.initial_clock == 0.25);
    CHECK_FALSE(r.options.animation.is_animation());
    // clock_on as POV-Ray 3.7 reads it (tests/runtime/animation_test.cpp):
    // 1 under +K0.25, 0 in a still without it.
    const auto clock_on = [](const hexant::language::ParseOptions& options) {
        hexant::language::ParseOptions quiet = options;
        std::ostringstream messages;
        quiet.messages = &messages;
        const auto scene = hexant::language::parse_scene_text("#if (clock_on) sphere { 0, 1 } #end",
                                                              "test.pov", quiet);
        return scene.objects.size();
    };
    CHECK(clock_on(r.options) == 1);
    hexant::app::SceneArguments still;
    still.files = {"scene.pov"};
    CHECK(clock_on(hexant::app::resolve(still).options) == 0);
}

TEST_CASE("bad .ini values and flags are errors naming the place", "[app][ini]") {
    const auto bad = write("bad.ini", "Width=126\nHeight=lots\n");
    hexant::app::SceneArguments arguments;
    arguments.files = {"scene.pov", bad.string()};
    REQUIRE_THROWS_WITH(hexant::app::resolve(arguments),
                        Catch::Contains("bad.ini:2") && Catch::Contains("Height"));
    hexant::app::SceneArguments two_scenes;
    two_scenes.files = {"a.pov", "b.pov"};
    REQUIRE_THROWS_WITH(hexant::app::resolve(two_scenes), Catch::Contains("more than one scene"));
    hexant::app::SceneArguments no_scene;
    no_scene.files = {write("empty.ini", "Width=3\n").string()};
    REQUIRE_THROWS_WITH(hexant::app::resolve(no_scene), Catch::Contains("no scene"));
    hexant::app::SceneArguments bad_clock;
    bad_clock.files = {"a.pov"};
    bad_clock.clock_range = "0:x";
    REQUIRE_THROWS_WITH(hexant::app::resolve(bad_clock), Catch::Contains("--clock"));
    for (const char* clock : {"nan:1", "0:inf", "nan"}) {
        hexant::app::SceneArguments nan_clock;
        nan_clock.files = {"a.pov"};
        nan_clock.clock_range = clock;
        REQUIRE_THROWS_WITH(hexant::app::resolve(nan_clock), Catch::Contains("finite"));
    }
    hexant::app::SceneArguments too_many_frames;
    too_many_frames.files = {"a.pov"};
    too_many_frames.frame_count = 2147483647;
    REQUIRE_THROWS_WITH(hexant::app::resolve(too_many_frames),
                        Catch::Contains("more than 1000000 frames"));
    too_many_frames.frame_count = 1'000'000;
    CHECK(hexant::app::resolve(too_many_frames).options.animation.final_frame == 1'000'000);
    hexant::app::SceneArguments nan_shutter;
    nan_shutter.files = {"a.pov"};
    nan_shutter.shutter = std::nan("");
    REQUIRE_THROWS_WITH(hexant::app::resolve(nan_shutter), Catch::Contains("--shutter"));
    hexant::app::SceneArguments bad_declare;
    bad_declare.files = {"a.pov"};
    bad_declare.declares = {"NoValue"};
    REQUIRE_THROWS_WITH(hexant::app::resolve(bad_declare), Catch::Contains("NAME=VALUE"));
}

TEST_CASE("the loop limit flag takes 1 to 10^12, never a wrapped -1", "[app]") {
    CHECK(*parse("--max-loop-iterations 1000").max_loop_iterations == 1000);
    CHECK_THROWS(parse("--max-loop-iterations -1"));
    CHECK_THROWS(parse("--max-loop-iterations 0"));
    CHECK_THROWS(parse("--max-loop-iterations 1e13"));
}

TEST_CASE("every limit has a flag, and frames and pixels are checked before any work",
          "[app][limits]") {
    const auto limits = resolved(
                            "--max-iterations 7 --max-macro-depth 8 --max-include-depth 9 "
                            "--max-string-length 10 --max-array-memory 11 --max-frames 12 "
                            "--max-pixels 130000 --max-loop-iterations 14 --max-text-read 15 "
                            "--max-debug-output 16 --max-objects 17 --max-triangles 18")
                            .options.limits;
    CHECK(limits.total_iterations == 7);
    CHECK(limits.macro_depth == 8);
    CHECK(limits.include_depth == 9);
    CHECK(limits.string_length == 10);
    CHECK(limits.array_memory == std::size_t(11) << 20);
    CHECK(limits.frames == 12);
    CHECK(limits.image_pixels == 130000);
    CHECK(limits.loop_iterations == 14);
    CHECK(limits.text_read == 15);
    CHECK(limits.debug_output == 16);
    CHECK(limits.objects == 17);
    CHECK(limits.triangles == 18);
    for (const char* wrapped :
         {"--max-iterations -1", "--max-text-read -1", "--max-string-length -1",
          "--max-debug-output -1", "--max-objects 0", "--max-triangles -1", "--max-array-memory -1",
          "--max-frames 0", "--max-pixels 0", "--max-macro-depth -1"})
        CHECK_THROWS(parse(wrapped));

    // -W 100000 -H 100000 ended in std::bad_alloc; now it is refused by name.
    REQUIRE_THROWS_WITH(
        resolved("-W 100000 -H 100000"),
        Catch::Contains("100000 by 100000 pixels") && Catch::Contains("--max-pixels"));
    CHECK_NOTHROW(resolved("-W 10000 -H 10000"));
    CHECK_NOTHROW(resolved("-W 100000 -H 100000 --max-pixels 10000000000"));
    // --frame-count 2147483647 overflowed an int loop over frames.
    REQUIRE_THROWS_WITH(
        resolved("--frame-count 2147483647"),
        Catch::Contains("more than 1000000 frames") && Catch::Contains("--max-frames"));
    CHECK_THROWS(resolved("--frame-count 13 --max-frames 12"));
    CHECK_NOTHROW(resolved("--frame-count 12 --max-frames 12"));
    // From an .ini file too: the whole range of int.
    const auto ini = write("frames.ini", "Initial_Frame=-2147483648\nFinal_Frame=2147483647\n");
    hexant::app::SceneArguments from_ini;
    from_ini.files = {"a.pov", ini.string()};
    CHECK_THROWS_WITH(hexant::app::resolve(from_ini), Catch::Contains("frames -2147483648 to"));
}

TEST_CASE("command-line numbers are finite: the clock and the shutter", "[app][parameters]") {
    CHECK_THROWS_WITH(resolved("--clock nan:1"), Catch::Contains("finite"));
    CHECK_THROWS_WITH(resolved("--clock 0:inf --frame-count 2"), Catch::Contains("finite"));
    CHECK_THROWS_WITH(resolved("--clock nan"), Catch::Contains("finite"));
    CHECK_THROWS_WITH(resolved("--shutter nan"), Catch::Contains("[0, 1]"));
    CHECK_THROWS_WITH(resolved("--clock -1e308:1e308 --frame-count 2"),
                      Catch::Contains("overflows"));
    CHECK_NOTHROW(resolved("--clock -1e300:1e300 --frame-count 2"));
}
