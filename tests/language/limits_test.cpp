// Each limit of language/limits.hpp: a scene that passes it stops with an
// error at the place it did so, and one just inside it reads.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "language/interpreter.hpp"
#include "runtime/motion/transform.hpp"
#include "scene_text.hpp"
#include "tests/image/declared_size_files.hpp"
#include "tests/sanitizer.hpp"

using hexant::language::ParseOptions;
using hexant::language::SceneError;
using hexant::test::error_of;
using hexant::test::reads;
namespace fs = std::filesystem;

namespace {

bool contains(const SceneError& e, const std::string& part) {
    return e.message().find(part) != std::string::npos;
}

}  // namespace

TEST_CASE("the total iteration budget spans nested loops and macro calls", "[limits]") {
    ParseOptions options;
    options.limits.loop_iterations = 100;  // each loop alone stays inside it
    options.limits.total_iterations = 1000;
    const std::string nested =
        "#declare I = 0;\n#while (I < 40)\n  #declare J = 0;\n"
        "  #while (J < 40) #declare J = J + 1; #end\n"
        "  #declare I = I + 1;\n#end\n";
    const SceneError e = error_of(nested, options);
    CHECK(contains(e, "more than 1000 loop iterations and macro calls"));
    CHECK(contains(e, "--max-iterations"));
    CHECK(e.places().front().line == 4);  // the inner loop's #while
    CHECK(e.places().front().column == 3);
    options.limits.total_iterations = 40 * 41 + 40;  // every step of it, the last false tests free
    reads(nested, options);

    // Macro calls count too: a loop of calls.
    options.limits.total_iterations = 50;
    const SceneError m = error_of("#macro M() #end\n#for (I, 1, 30) M() #end\n", options);
    CHECK(contains(m, "macro calls in all"));
    CHECK(m.places().front().line == 2);
}

TEST_CASE("the text read is bounded: a loop's turns, macro calls and includes read again",
          "[limits]") {
    // The fuzzer's find (tests/scenes/fuzz_found/switch_skip_hang.pov): a
    // loop that never ends, each turn stepping over a long body, stayed
    // under the iteration limits for hours. Here a 10 KB body.
    // (A loop's body starts after the blanks and comments that follow its
    // header, hence the #declare first.)
    const std::string body = "#declare X = 0; /*" + std::string(10'000, '.') + "*/";
    ParseOptions options;
    options.limits.text_read = 1'000'000;
    const SceneError w = error_of(
        "#declare I = 0;\n#while (1)\n  #switch (I) #case (1) " + body + " #end\n#end\n", options);
    CHECK(contains(w, "more than 1000000 bytes of text"));
    CHECK(contains(w, "--max-text-read"));
    CHECK(w.places().front().line == 2);  // the loop that read it again
    // A for loop and macro calls count the same way; 90 turns of the body
    // fit, 110 do not.
    reads("#for (I, 1, 90) " + body + " #end", options);
    const SceneError f = error_of("#for (I, 1, 110) " + body + " #end", options);
    CHECK(contains(f, "bytes of text"));
    // Its report shows 160 bytes of the 10 KB line from the place, not all.
    const std::string report = f.formatted();
    CHECK(report.size() < 600);
    CHECK(report.find("\n    #for (I, 1, 110) #declare X = 0; /*....") != std::string::npos);
    CHECK(report.find("....\n    ^\n") != std::string::npos);
    // In the middle of a long line, the caret still points at the place.
    hexant::language::ErrorPlace middle{"long.pov", 1, 5001, std::string(10'000, 'a'), {}};
    middle.source_line[5000] = 'X';
    const std::string shown = SceneError("bad", middle).formatted();
    CHECK(shown.find("\n    ..." + std::string(80, 'a') + "X" + std::string(79, 'a') +
                     "...\n    ..." + std::string(80, ' ') + "^\n") != std::string::npos);
    // A place keeps only that part of its line (a runaway recursion makes
    // hundreds of places on one line), and reports the same; at the line's
    // start and end too.
    for (const std::size_t column : {std::size_t(1), std::size_t(3), std::size_t(5001),
                                     std::size_t(9990), std::size_t(10'001)}) {
        hexant::language::ErrorPlace whole = middle, kept = middle;
        whole.column = kept.column = column;
        kept.set_source_line(middle.source_line);
        CHECK(kept.source_line.size() == 160);
        CHECK(SceneError("bad", kept).formatted() == SceneError("bad", whole).formatted());
    }
    const std::string macro = "#macro M() " + body + " #end\n";
    reads(macro + "#for (I, 1, 90) M() #end", options);  // the turns are short, the calls long
    const SceneError m = error_of(macro + "#for (I, 1, 110) M() #end", options);
    CHECK(contains(m, "bytes of text"));

    // An include counts its file each time it is read.
    const fs::path folder = fs::temp_directory_path() / "hexant_text_read_test";
    fs::create_directories(folder);
    std::ofstream(folder / "long.inc") << body;
    std::ofstream(folder / "twice.pov") << "#for (I, 1, 90) #include \"long.inc\" #end\n";
    std::ofstream(folder / "many.pov") << "#for (I, 1, 110) #include \"long.inc\" #end\n";
    std::ostringstream messages;
    options.messages = &messages;
    CHECK_NOTHROW(hexant::language::parse_scene_file(folder / "twice.pov", options));
    // Refused before it is read: the limit is checked against its size.
    CHECK_THROWS_WITH(
        hexant::language::parse_scene_file(folder / "many.pov", options),
        Catch::Contains("long.inc': its 10020 bytes would take the scene's reading over "
                        "its limit of text"));
    fs::remove_all(folder);
}

TEST_CASE("an error's source line is shown as the terminal should see it", "[limits]") {
    // One space a character under the line, not a byte: the caret under BAD.
    const std::string u8 =
        error_of("#declare S = \"h\xC3\xA9llo w\xC3\xB6rld\";  BAD\n").formatted();
    CHECK(u8.find("\n    " + std::string(29, ' ') + "^\n") != std::string::npos);
    // Control characters (a bare carriage return, an escape, a NUL) are
    // shown as '?', and a NUL in the way is named, not printed.
    const std::string ctrl = error_of("sphere{0,1}\rBAD \x1b[31m\n").formatted();
    CHECK(ctrl.find('\x1b') == std::string::npos);
    CHECK(ctrl.find('\r') == std::string::npos);
    CHECK(ctrl.find("    sphere{0,1}?BAD ?[31m\n") != std::string::npos);
    const SceneError nul = error_of(std::string("sphere{0,1}\n\0\0", 15));
    CHECK(contains(nul, "found the control character 0x00"));
    CHECK(std::string(nul.what()).find("0x00") != std::string::npos);  // not cut at the NUL
    // A long line cut around the place is cut between characters.
    std::string line;
    for (int i = 0; i < 100; ++i) line += "#declare S = \"\xC3\xA9\xE6\x97\xA5\";\n";
    std::string one_line = line;
    std::replace(one_line.begin(), one_line.end(), '\n', ' ');
    const std::string cut = error_of(one_line + " BAD").formatted();
    const std::size_t shown = cut.find("\n    ...");
    REQUIRE(shown != std::string::npos);
    const std::size_t shown_end = cut.find('\n', shown + 1);
    const std::string excerpt = cut.substr(shown + 8, shown_end - shown - 8);
    CHECK((static_cast<unsigned char>(excerpt.front()) & 0xC0) != 0x80);  // starts on a character
    CHECK(excerpt.find(" BAD") != std::string::npos);
}

TEST_CASE("the scene file itself: a regular file, within the text a reading may go over",
          "[limits]") {
    ParseOptions options;
    std::ostringstream messages;
    options.messages = &messages;
    if (fs::exists("/dev/zero"))
        CHECK_THROWS_WITH(hexant::language::parse_scene_file("/dev/zero", options),
                          Catch::Contains("not a regular file"));
    const fs::path folder = fs::temp_directory_path() / "hexant_scene_size_test";
    fs::create_directories(folder);
    std::ofstream(folder / "big.pov") << "// " << std::string(5000, '.') << "\n";
    options.limits.text_read = 4000;
    CHECK_THROWS_WITH(
        hexant::language::parse_scene_file(folder / "big.pov", options),
        Catch::Contains(
            "5004 bytes would take the scene's reading over its limit of text, 4000 bytes left"));
    options.limits.text_read = 6000;
    CHECK_NOTHROW(hexant::language::parse_scene_file(folder / "big.pov", options));
    fs::remove_all(folder);
}

TEST_CASE("a string longer than the limit stops where it would be made", "[limits]") {
    ParseOptions options;
    options.limits.string_length = 1000;
    const SceneError e = error_of(
        "#declare S = \"abcdefgh\";\n#while (1)\n"
        "  #declare S = concat(S, S);\n#end\n",
        options);
    CHECK(contains(e, "concat()'s result would be 1024 characters long"));
    CHECK(contains(e, "--max-string-length"));
    CHECK(e.places().front().line == 3);
    reads("#declare S = concat(\"" + std::string(500, 'a') + "\", \"" + std::string(500, 'b') +
              "\");",
          options);
    // Any function's string: vstr of a long separator.
    const SceneError v = error_of(
        "#declare S = vstr(5, <1,2,3,4,5>, \"" + std::string(300, '-') + "\", 0, 0);", options);
    CHECK(contains(v, "vstr()'s result"));
}

TEST_CASE("the arrays' memory is held against its limit, and given back", "[limits]") {
    ParseOptions options;
    options.limits.array_memory = 1 << 20;  // 1 MiB: 43,690 slots of 24 bytes
    const SceneError e = error_of("#declare A = array[10]\n#declare B = array[100000]\n", options);
    CHECK(contains(e, "more than 1.0 MiB"));
    CHECK(contains(e, "--max-array-memory"));
    CHECK(e.places().front().line == 2);
    // An array rebuilt in a loop holds what one declaration does (the new
    // array, its copy into the name, the old one) however many times it runs.
    reads("#for (I, 1, 100) #declare A = array[10000]; #end\n", options);
    // Values set in an array count: strings of 1000 characters.
    options.limits.array_memory = 200'000;
    const SceneError s = error_of(
        "#declare A = array[1000]\n#for (I, 0, 999)\n"
        "  #declare A[I] = str(I, 1000, 0);\n#end\n",
        options);
    CHECK(contains(s, "arrays and strings would hold more than"));
    CHECK(s.places().front().line == 3);
}

TEST_CASE("strings held in variables count against the same memory, and are given back",
          "[limits]") {
    ParseOptions options;
    options.limits.array_memory = 1 << 20;
    // S: 163,840 characters (ten, doubled fourteen times).
    const std::string s =
        "#declare S = \"0123456789\";\n"
        "#for (K, 1, 14) #declare S = concat(S, S); #end\n";
    // S and five copies hold 983,040 bytes; the sixth copy passes 1 MiB.
    const SceneError e = error_of(s + "#declare S1 = S;\n#declare S2 = S;\n#declare S3 = S;\n"
                                      "#declare S4 = S;\n#declare S5 = S;\n#declare S6 = S;\n",
                                  options);
    CHECK(contains(e, "arrays and strings would hold more than 1.0 MiB"));
    CHECK(e.places().front().line == 8);
    // One name set again and again holds one string's worth; #undef and a
    // macro's end give theirs back; a macro's string parameter and locals
    // count while it runs.
    reads(s + "#for (I, 1, 100) #declare T = concat(S, str(I, 0, 0)); #end\n", options);
    reads(s + "#for (I, 1, 100) #declare T = concat(S, S, S); #undef T #end\n", options);
    reads(s + "#macro M(A) #local L = concat(A, A); #end\n#for (I, 1, 100) M(S) #end\n", options);
    CHECK(contains(
        error_of(s + "#macro M(A) #local L = concat(A, A, A, A, A, A); #end\nM(S)\n", options),
        "arrays and strings would hold more than 1.0 MiB"));
}

TEST_CASE("include and macro depths stop at their limits", "[limits]") {
    ParseOptions options;
    options.limits.macro_depth = 10;
    const SceneError m = error_of("#macro R(N) R(N + 1) #end\nR(0)\n", options);
    CHECK(contains(m, "nested more than 10 deep"));
    CHECK(contains(m, "--max-macro-depth"));
    // The report shows the first and last ten calls, not all of them.
    options.limits.macro_depth = 60;
    const std::string report = error_of("#macro R(N) R(N + 1) #end\nR(0)\n", options).formatted();
    CHECK(report.find("... 40 more places like these ...") != std::string::npos);
    std::size_t notes = 0;
    for (auto at = report.find(": note:"); at != std::string::npos;
         at = report.find(": note:", at + 1))
        ++notes;
    CHECK(notes == 20);
}

TEST_CASE("running out of memory while reading is an error at the place", "[limits]") {
    // A limit raised past what the process may have: the allocation fails
    // and the reader names the place instead of ending in std::terminate.
    // In a child whose address space is capped at 1 GiB, so that the test
    // asks for no more than that whatever the machine.
    if (hexant::test::kAddressSanitizer) {
        WARN(
            "not run under AddressSanitizer: its shadow memory needs more address space than the "
            "cap");
        return;
    }
    const pid_t child = fork();
    REQUIRE(child >= 0);
    if (child == 0) {
        rlimit cap{rlim_t(1) << 30, rlim_t(1) << 30};
        if (setrlimit(RLIMIT_AS, &cap) != 0) _exit(3);
        ParseOptions options;
        options.limits.array_memory = std::size_t(1) << 40;
        std::ostringstream messages;
        options.messages = &messages;
        try {
            hexant::language::parse_scene_text("#declare A = 1;\n#declare B = array[100000000]\n",
                                               "limits.pov", options);
        } catch (const SceneError& e) {
            _exit(e.message().find("out of memory here") != std::string::npos &&
                          e.places().front().line == 2
                      ? 0
                      : 2);
        } catch (...) {
            _exit(4);
        }
        _exit(5);
    }
    int status = 0;
    REQUIRE(waitpid(child, &status, 0) == child);
    REQUIRE(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 0);
}

TEST_CASE("a transform built up in a loop costs the same at every turn, or stops at its limit",
          "[limits]") {
    // Constant steps past the listed ones join as one matrix: 20,000 turns
    // keep a short transform (each turn copied all of it before: quadratic).
    const std::string turtle =
        "#declare T = transform { translate 0 };\n"
        "#for (I, 1, 20000) #declare T = transform { T translate <0.0001, 0, 0> rotate y * 0.01 }; "
        "#end\n"
        "sphere { 0, 1 transform T }\n";
    ParseOptions options;
    const auto scene = hexant::language::parse_scene_text(turtle, "turtle.pov", options);
    const auto& steps = scene.objects.front()->transform.steps();
    CHECK(steps.size() <= hexant::runtime::kListedSteps);
    // The same map as the steps one by one: 20,000 turns of 0.01 degrees
    // about y, each after a step along x.
    glm::dmat4 expected(1.0);
    for (int i = 0; i < 20000; ++i) {
        expected = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0001, 0, 0)) * expected;
        expected = glm::rotate(glm::dmat4(1.0), glm::radians(0.01), glm::dvec3(0, 1, 0)) * expected;
    }
    const glm::dmat4 got = scene.objects.front()->transform.matrix_at(0.0);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) CHECK(got[i][j] == Approx(expected[i][j]).margin(1e-9));
    // Steps of clock cannot join: past the limit, an error at the place.
    options.animation.final_frame = 4;
    const SceneError e = error_of(
        "#declare T = transform { translate 0 };\n"
        "#for (I, 1, 3000) #declare T = transform { T translate <clock * 0.0001, 0, 0> }; #end\n",
        options);
    CHECK(contains(e, "a transform of more than 2000 steps that depend on clock"));
    CHECK(e.places().front().line == 2);
}

TEST_CASE("objects are counted where they are made: copies, members, glyphs", "[limits]") {
    // (issue 45) A union doubled 30 times asked for 2^30 spheres; each
    // doubling is refused where the count passes the limit, before any
    // walk over its members (which would take 2^n steps).
    ParseOptions options;
    options.limits.objects = 1000;
    const std::string doubled =
        "#declare U = sphere { 0, 1 }\n#for (I, 1, 60)\n"
        "#declare U = union { object { U } object { U translate x } }\n#end\n";
    const SceneError e = error_of(doubled, options);
    CHECK(contains(e, "would make 1024 objects"));
    CHECK(contains(e, "--max-objects"));
    CHECK(e.places().front().line == 3);
    // 70 doublings saturate, never wrap (a limit past what --max-objects takes).
    options.limits.objects = (std::uint64_t(1) << 62) - 1;
    std::string seventy = doubled;
    seventy.replace(seventy.find("1, 60"), 5, "1, 70");
    CHECK(contains(error_of(seventy, options), "would make more than 2^62 objects"));
    // The scene's total: 10 of 100 members placed apart.
    options.limits.objects = 999;
    const std::string placed =
        "#declare U = union {\n#for (I, 1, 100) sphere { I * x, 1 } #end\n}\n"
        "#for (I, 1, 10) object { U translate I * y } #end\n";
    const SceneError total = error_of(placed, options);
    CHECK(contains(total, "the scene would make more than 999 objects"));
    CHECK(total.places().front().line == 4);
    options.limits.objects = 1000;
    reads(placed, options);
    // A copy of a clipped object counts its clip once: 20 turns of clipping
    // by the last copy make 21 objects, not 2^20 (a copy's count already
    // held its clips, and was counted again once).
    options.limits.objects = 21;
    reads(
        "#declare O = sphere { 0, 1 }\n#for (I, 1, 20) #declare O = sphere { 0, 1 clipped_by "
        "{ object { O } } } #end\nobject { O }\n",
        options);
    options.limits.objects = 20;
    CHECK(contains(error_of("#declare O = sphere { 0, 1 }\n#for (I, 1, 20) #declare O = sphere "
                            "{ 0, 1 clipped_by { object { O } } } #end\nobject { O }\n",
                            options),
                   "would make 21 objects"));
    // clipped_by objects count; a text's glyphs count before they are laid out.
    options.limits.objects = 2;
    CHECK(contains(
        error_of("sphere { 0, 1 clipped_by { plane { y, 0 } } clipped_by { plane { x, 0 } } }\n",
                 options),
        "would make 3 objects"));
    CHECK(contains(error_of("text { ttf \"timrom.ttf\" \"abc\" 0.1, 0 }\n", options),
                   "this text has 3 characters"));
    // Laid out, its glyphs count in the scene's total: two texts of 3 are 6.
    options.limits.objects = 5;
    CHECK(contains(error_of("text { ttf \"timrom.ttf\" \"abc\" 0.1, 0 }\n"
                            "text { ttf \"timrom.ttf\" \"abc\" 0.1, 0 }\n",
                            options),
                   "the scene would make more than 5 objects"));
}

TEST_CASE("mesh triangles are counted as they are read", "[limits]") {
    ParseOptions options;
    options.limits.triangles = 3;
    const std::string tri = "triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }\n";
    reads("mesh {\n" + tri + tri + tri + "}\n", options);
    const SceneError e = error_of("mesh {\n" + tri + tri + tri + tri + "}\n", options);
    CHECK(contains(e, "more than 3 triangles"));
    CHECK(contains(e, "--max-triangles"));
    CHECK(e.places().front().line == 5);
    // Over the whole scene, mesh2's faces too.
    const std::string mesh2 =
        "mesh2 { vertex_vectors { 3, <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }\n"
        "face_indices { 2, <0, 1, 2>, <0, 2, 1> } }\n";
    reads(mesh2, options);
    CHECK(error_of("mesh {\n" + tri + tri + "}\n" + mesh2, options).places().front().line == 6);
}

TEST_CASE("a long reading says how far it has come", "[limits]") {
    ParseOptions options;
    options.progress_delay = 0.0;
    std::vector<ParseOptions::Progress> said;
    options.progress = [&](const ParseOptions::Progress& p) { said.push_back(p); };
    reads("mesh {\n#for (I, 1, 5000) triangle { <I, 0, 0>, <I + 1, 0, 0>, <I, 1, 0> } #end\n}\n",
          options);
    // (The first call after 1024 steps and triangles counted; later ones a
    // second apart.)
    REQUIRE(!said.empty());
    CHECK(said.front().steps + said.front().triangles >= 1023);
    CHECK(said.front().triangles > 0);
    CHECK(said.front().seconds >= 0.0);
    // Without a delay passed, nothing.
    said.clear();
    options.progress_delay = 3600.0;
    reads("#for (I, 1, 5000) #end\n", options);
    CHECK(said.empty());
}

TEST_CASE("an image a scene reads is held to --max-pixels before it is decoded",
          "[limits][image]") {
    // A PNG of 61 bytes declaring 32768 by 32768 gray pixels: read as an
    // image_map, a bump_map or a height_field, it stops at the place with
    // the size, the limit and the flag, in a child whose address space is
    // capped at 1 GiB: decoding it would take 3 GB (12 GB as floats).
    if (hexant::test::kAddressSanitizer) {
        WARN("not run under AddressSanitizer: its shadow memory needs more than the cap");
        return;
    }
    const fs::path dir = fs::temp_directory_path() / ("hexant_limits_" + std::to_string(getpid()));
    fs::create_directories(dir);
    hexant::test::write_png_header(dir / "huge.png", 32768, 32768);
    const std::string scenes[] = {
        "#declare A = 1;\nsphere { 0, 1 pigment { image_map { png \"huge.png\" } } }\n",
        "#declare A = 1;\nsphere { 0, 1 normal { bump_map { png \"huge.png\" } } }\n",
        "#declare A = 1;\nheight_field { png \"huge.png\" }\n"};
    for (const std::string& text : scenes) {
        INFO(text);
        const pid_t child = fork();
        REQUIRE(child >= 0);
        if (child == 0) {
            rlimit cap{rlim_t(1) << 30, rlim_t(1) << 30};
            if (setrlimit(RLIMIT_AS, &cap) != 0) _exit(3);
            ParseOptions options;
            options.include_paths = {dir.string()};
            std::ostringstream messages;
            options.messages = &messages;
            try {
                hexant::language::parse_scene_text(text, "limits.pov", options);
            } catch (const SceneError& e) {
                const bool said = contains(e, "huge.png") &&
                                  contains(e, "declares 32768 by 32768 pixels") &&
                                  contains(e, "limit of 100000000 pixels") &&
                                  contains(e, "--max-pixels N raises it");
                _exit(said && e.places().front().line == 2 ? 0 : 2);
            } catch (...) {
                _exit(4);
            }
            _exit(5);
        }
        int status = 0;
        REQUIRE(waitpid(child, &status, 0) == child);
        REQUIRE(WIFEXITED(status));
        CHECK(WEXITSTATUS(status) == 0);
    }
    fs::remove_all(dir);
}

TEST_CASE("an image within --max-pixels reads, and one pixel over it does not", "[limits][image]") {
    // tiles.png is 8 by 6: the scene's limit is the frame's limit too.
    ParseOptions options;
    options.include_paths = {std::string(HEXANT_SOURCE_DIR) +
                             "/tests/tracer/pov_reference/textures"};
    const std::string image_map = "sphere { 0, 1 pigment { image_map { png \"tiles.png\" } } }\n";
    const std::string height_field = "height_field { png \"tiles.png\" }\n";
    for (const std::string& text : {image_map, height_field}) {
        INFO(text);
        options.limits.image_pixels = 48;
        reads(text, options);
        options.limits.image_pixels = 47;
        const SceneError e = error_of(text, options);
        CHECK(contains(e, "declares 8 by 6 pixels, more than the limit of 47"));
        CHECK(e.places().front().line == 1);
    }
}
