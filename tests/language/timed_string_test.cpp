// Strings that depend on clock (language/timed_string.hpp, timed_call.hpp):
// str(), chr(), concat() and the rest split time where what they read of
// an argument changes, exactly at the double where printf's rounding (or
// the integer part) changes; a branch on clock that sets two strings makes
// one piecewise string; #include of such a name reads each file for the
// time its name holds.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>

#include "language/builtins.hpp"
#include "language/interpreter.hpp"
#include "runtime/time/interval.hpp"
#include "scene_text.hpp"

using hexant::language::format_number;
using hexant::language::ParseOptions;
using hexant::runtime::SceneDescription;
using hexant::test::animation;
using hexant::test::error_of;

namespace rt = hexant::runtime;

namespace {

SceneDescription read_with(const std::string& text, ParseOptions options) {
    std::ostringstream ignored;
    options.messages = &ignored;
    return hexant::language::parse_scene_text(text, "test.pov", options);
}

SceneDescription read(const std::string& text, std::ostringstream* messages = nullptr) {
    ParseOptions options = animation();
    std::ostringstream ignored;
    options.messages = messages ? messages : &ignored;
    return hexant::language::parse_scene_text(text, "test.pov", options);
}

double before(double t) {
    return rt::interval_detail::next_down(t);
}
double after(double t) {
    return rt::interval_detail::next_up(t);
}

}  // namespace

TEST_CASE("str() on clock switches exactly where printf's rounding changes", "[language][time]") {
    // The sphere lives where str(clock * 10, 0, 1) is "3.2": from the first
    // double whose product rounds to 3.2 to the last, as POV-Ray's sprintf
    // would print it at that clock.
    const auto scene = read(R"(
#if (strcmp(str(clock * 10, 0, 1), "3.2") = 0) sphere { 0, 1 } #end
#if (strcmp(str(clock, 0, 0), "1") = 0) box { 0, 1 } #end
)");
    REQUIRE(scene.objects.size() == 2);
    const rt::Lifetime& when = scene.objects[0]->lifetime;
    REQUIRE(when.pieces().size() == 1);
    const rt::Interval piece = when.pieces()[0];
    const auto text = [](double t) { return format_number(t * 10, 0, 1); };
    CHECK(text(piece.lo) == "3.2");
    CHECK(text(before(piece.lo)) == "3.1");
    CHECK(text(piece.hi) == "3.2");
    CHECK(text(after(piece.hi)) == "3.3");
    CHECK(std::fabs(piece.lo - 0.315) < 1e-15);
    CHECK(std::fabs(piece.hi - 0.325) < 1e-15);
    // "%.0f" rounds half to even at the exact binary value: 0.5 prints "0".
    const rt::Interval one = scene.objects[1]->lifetime.pieces().at(0);
    CHECK(format_number(one.lo, 0, 0) == "1");
    CHECK(format_number(before(one.lo), 0, 0) == "0");
    CHECK(one.lo == after(0.5));
}

TEST_CASE("str(frame_number), chr() and val() give each frame's value", "[language][time]") {
    const auto scene = read(R"(
#declare F = str(frame_number, 0, 0);
#if (val(F) = 3) sphere { 0, 1 } #end
#if (strcmp(chr(64 + frame_number), "E") = 0) box { 0, 1 } #end
#if (strlen(concat(F, "x")) = 2) cylinder { 0, y, 1 } #end
)");
    REQUIRE(scene.objects.size() == 3);
    // Frame 3 holds its clock up to frame 4's (the shutter of frame n opens
    // at its clock, about (n - 1)/7, and lasts to the next).
    const double start3 = scene.animation.clock_of_frame(3),
                 start4 = scene.animation.clock_of_frame(4),
                 start5 = scene.animation.clock_of_frame(5);
    const rt::Lifetime& three = scene.objects[0]->lifetime;
    CHECK(three.contains(start3));
    CHECK_FALSE(three.contains(before(start3)));
    CHECK(three.contains(before(start4)));
    CHECK_FALSE(three.contains(start4));
    const rt::Lifetime& five = scene.objects[1]->lifetime;
    CHECK(five.contains(start5));
    CHECK_FALSE(five.contains(before(start5)));
    CHECK_FALSE(five.contains(0.0));
    // One-digit frame numbers: all of frames 1 to 8.
    CHECK(scene.objects[2]->lifetime.contains(0.0));
    CHECK(scene.objects[2]->lifetime.contains(1.0));
}

TEST_CASE("a branch on clock that sets two strings makes one piecewise string",
          "[language][time]") {
    std::ostringstream messages;
    const auto scene = read(R"(
#if (clock < 0.5) #declare T = "early"; #else #declare T = "late"; #end
#declare U = strupr(T);
#debug concat(U, "\n")
#if (strcmp(U, "LATE") = 0) sphere { 0, 1 } #end
#if (clock < 0.5) #declare Same = "x"; #else #declare Same = "x"; #end
#if (strcmp(Same, "x") != 0) box { 0, 1 } #end
)",
                            &messages);
    REQUIRE(scene.objects.size() == 1);
    CHECK(scene.objects[0]->lifetime.contains(0.5));
    CHECK_FALSE(scene.objects[0]->lifetime.contains(before(0.5)));
    // #debug says each piece's text after the time it holds.
    const std::string said = messages.str();
    CHECK(said.find("[clock 0 to 0.49999999999999994] EARLY\n") != std::string::npos);
    CHECK(said.find("[clock 0.5 to ") != std::string::npos);
    CHECK(said.find("] LATE\n") != std::string::npos);
}

TEST_CASE("strings compare with = != < <= > >= as POV-Ray's strcmp", "[language][time]") {
    // POV-Ray's Parse_Rel_String_Term: the sign of strcmp against 0, for
    // plain strings and for strings that depend on clock (then the
    // comparison switches where the text does).
    const auto scene = read(R"(
#declare A = "abc";
#if (A = "abc") sphere { 0, 1 } #end
#if (A != "") sphere { 0, 2 } #end
#if (A < "abd") sphere { 0, 3 } #end
#if (A <= "abc") sphere { 0, 4 } #end
#if ("b" > A) sphere { 0, 5 } #end
#if ("ab" >= A) box { 0, 1 } #end
#if (A != "abc") box { 0, 2 } #end
#if (str(clock, 0, 0) != "0") cylinder { 0, y, 1 } #end
)");
    REQUIRE(scene.objects.size() == 6);
    for (int i = 0; i < 5; ++i) CHECK(scene.objects[i]->lifetime.is_always());
    // "%.0f": "0" up to 0.5 (half to even), "1" after it.
    const rt::Lifetime& later = scene.objects[5]->lifetime;
    CHECK_FALSE(later.contains(0.5));
    CHECK(later.contains(after(0.5)));
    CHECK(error_of("#if (\"a\" < 1) #end").formatted().find("cannot apply") != std::string::npos);
}

TEST_CASE("#include of a name on clock reads each file for its time", "[language][time][include]") {
    namespace fs = std::filesystem;
    const fs::path root = fs::temp_directory_path() / "hexant_timed_include_test";
    fs::remove_all(root);
    fs::create_directories(root);
    for (int i = 1; i <= 8; ++i)
        std::ofstream(root / ("f" + std::to_string(i) + ".inc"))
            << "sphere { <" << i << ", 0, 0>, 0.3 } #declare Last = " << i << ";\n";
    std::ofstream(root / "main.pov")
        << "#include concat(\"f\", str(frame_number, 0, 0), \".inc\")\n"
           "sphere { <Last, 1, 0>, 0.1 }\n";
    ParseOptions options = animation();
    std::ostringstream messages;
    options.messages = &messages;
    const auto scene = hexant::language::parse_scene_file(root / "main.pov", options);
    REQUIRE(scene.objects.size() == 9);
    for (int i = 1; i <= 8; ++i) {
        INFO("frame " << i);
        const rt::Lifetime& when = scene.objects[static_cast<std::size_t>(i - 1)]->lifetime;
        const double start = scene.animation.clock_of_frame(i);
        CHECK(when.contains(start));
        CHECK_FALSE(when.contains(before(start)));
        CHECK_FALSE(when.contains(after(when.pieces().back().hi)));
    }
    // The variable each file set: piecewise, each frame's own.
    const auto& marker = std::get<rt::Sphere>(scene.objects[8]->shape);
    CHECK(marker.center(0.0).x == 1.0);
    CHECK(marker.center(scene.animation.clock_of_frame(4)).x == 4.0);
    CHECK(marker.center(before(scene.animation.clock_of_frame(4))).x == 3.0);
    CHECK(marker.center(1.0).x == 8.0);
    fs::remove_all(root);
}

TEST_CASE("strings on clock: the piece limit and where one string is needed", "[language][time]") {
    ParseOptions few = animation();
    few.limits.time_pieces = 100;
    // 10^3 texts over the animation, past a limit of 100: an error at the call.
    const auto many = error_of("#declare S = str(clock, 0, 3);\n", few);
    CHECK(many.formatted().find("test.pov:1:") != std::string::npos);
    CHECK(many.formatted().find("--max-time-pieces") != std::string::npos);
    // A width that moves continuously is read by its integer part: a few
    // pieces, not one a double.
    hexant::test::reads("#declare S = str(1, 2 + clock * 3, 0);\n", animation());
    // A file name on clock where no split is made yet: one string needed.
    const auto font = error_of("#declare S = str(clock, 0, 1); #version S;\n", animation());
    CHECK(font.formatted().find("test.pov:1:") != std::string::npos);
}

TEST_CASE("frame_number of a clock that runs backwards, and the last shutter closing",
          "[language][time]") {
    ParseOptions options = animation();
    options.animation.final_frame = 3;
    options.animation.initial_clock = 2.0;
    options.animation.final_clock = 1.0;
    const auto scene = read_with("#if (frame_number = 2) sphere { 0, 1 } #end\n", options);
    // Frame 2 opens at clock 1.5 and runs down to frame 3's 1: (1, 1.5].
    REQUIRE(scene.objects.size() == 1);
    const rt::Lifetime& two = scene.objects[0]->lifetime;
    CHECK(two.contains(1.5));
    CHECK_FALSE(two.contains(after(1.5)));
    CHECK(two.contains(after(1.0)));
    CHECK_FALSE(two.contains(1.0));
    // The animation's time ends before the last shutter closes (no sample
    // is there): a string of the frame after the last is never made.
    std::ostringstream messages;
    const auto last = read("#debug str(int(clock * 7), 0, 0)\n", &messages);
    CHECK(messages.str().find("] 8") == std::string::npos);
    CHECK(messages.str().find("] 7") != std::string::npos);
}

TEST_CASE("str() with a negative precision and strcmp() as POV-Ray gives them",
          "[language][time]") {
    std::ostringstream messages;
    read(
        "#debug concat(str(1/3, 0, -2), \"|\", str(2, 5, -1), \"|\", str(strcmp(\"a\", \"c\"), 0, "
        "0), \"|\",\n"
        "             str(strcmp(\"abc\", \"ab\"), 0, 0), \"|\", str(strcmp(\"ab\", \"ab\"), 0, "
        "0), \"\\n\")\n",
        &messages);
    // POV-Ray's Parse_Str prints "%f" (six places) for any negative
    // precision; UCS2_strcmp gives the difference of the first characters
    // that differ.
    CHECK(messages.str() == "0.333333|2.000000|-2|99|0\n");
}
