// Deep nesting is an error at its place, never a crash (issue 17): scenes a
// generator could write, each far deeper than the reader's stack allows,
// and the same constructs at depths real scenes use, which still read.
#include <sstream>
#include <string>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "runtime/objects/object.hpp"
#include "runtime/objects/object_factory.hpp"
#include "runtime/time/time_function.hpp"
#include "scene_text.hpp"

using hexant::language::ParseOptions;
using hexant::language::SceneError;

namespace {

std::string repeat(const std::string& s, int n) {
    std::string out;
    out.reserve(s.size() * std::size_t(n));
    for (int i = 0; i < n; ++i) out += s;
    return out;
}

// An animation of 4 frames: clock runs.
ParseOptions animation() {
    ParseOptions options;
    options.animation.final_frame = 4;
    return options;
}

// Reads the scene; returns the error's message, or "" when it reads.
std::string read(const std::string& text) {
    const auto e = hexant::test::read_error(text, animation(), "deep.pov");
    return e ? e->message() : "";
}

struct Deep {
    const char* what;
    std::string open, middle, close;
};

}  // namespace

TEST_CASE("nesting beyond the reader's stack is an error, not a crash", "[language][nesting]") {
    const Deep cases[] = {
        {"parentheses", "#declare X = ", "1", ";"},  {"vectors", "#declare V = ", "1", ";"},
        {"unary minus", "#declare X = ", "1", ";"},  {"#if", "", "sphere { 0, 1 }", ""},
        {"skipped #while", "#if (0) ", "", " #end"}, {"unions", "", "sphere { 0, 1 }", ""},
    };
    for (const Deep& d : cases) {
        const std::string what = d.what;
        const int n = 200000;
        std::string text;
        if (what == "parentheses")
            text = d.open + repeat("(", n) + d.middle + repeat(")", n) + d.close;
        if (what == "vectors")
            text = d.open + repeat("<", n) + d.middle + repeat(",0,0>", n) + d.close;
        if (what == "unary minus") text = d.open + repeat("-", n) + d.middle + d.close;
        if (what == "#if") text = repeat("#if (1) ", n) + d.middle + repeat(" #end", n);
        if (what == "skipped #while")
            text = d.open + repeat("#while (1) ", n) + repeat(" #end", n) + d.close;
        if (what == "unions") text = repeat("union { ", n) + d.middle + repeat(" }", n);
        INFO(what);
        const std::string message = read(text);
        CHECK(message.find("nested too deeply") != std::string::npos);
    }
    // A condition among a shape's parameters is looked at ahead (is its
    // branch a value?) by a parse of its own, guarded too: too deep to look
    // at, the branch is not taken for parameters, and that is the error.
    const int n = 200000;
    CHECK(read("sphere { #if " + repeat("(", n) + "1" + repeat(")", n) + " 0, 1 #end }")
              .find("expected the object's parameters but found '#if'") != std::string::npos);
}

TEST_CASE("nesting as deep as real scenes go still reads", "[language][nesting]") {
    CHECK(read("#declare X = " + repeat("(", 500) + "1" + repeat(")", 500) + ";") == "");
    CHECK(read("#declare X = " + repeat("-", 500) + "1;") == "");
    CHECK(read(repeat("/*", 200) + repeat("*/", 200) + " sphere { 0, 1 }") == "");
    // Comments take no stack however deep (read with a count), also where
    // blanks are skipped without the guard: after a directive's keyword
    // (the fuzzer's stack overflow), and in a condition looked at ahead.
    const std::string deep = repeat("/*", 200000) + repeat("*/", 200000);
    CHECK(read(deep + " sphere { 0, 1 }") == "");
    CHECK(read("#if " + deep + " (1) sphere { 0, 1 } #end") == "");
    CHECK(read("sphere { #if " + deep + " (1) 0, 1 #end }") == "");
    CHECK(read(repeat("/*", 3) + "*/ /* " + repeat("/*", 200000)).find("unterminated comment") !=
          std::string::npos);
    CHECK(read(repeat("#if (1) ", 200) + "sphere { 0, 1 }" + repeat(" #end", 200)) == "");
    CHECK(read(repeat("union { ", 200) + "sphere { 0, 1 } sphere { 1, 1 }" + repeat(" }", 200)) ==
          "");
}

TEST_CASE("a function of clock built up too deep is an error where it is made, not a crash",
          "[language][nesting]") {
    const auto loop = [](int n) {
        return "#declare X = clock; #declare I = 0;\n#while (I < " + std::to_string(n) +
               ")\n  #declare X = X + clock * 0.5;\n  #declare I = I + 1;\n#end\n"
               "sphere { <X, 0, 0>, 1 }\n";
    };
    // Freeing, compiling or printing 300,000 nested operations overflowed
    // the stack; the limit stops it at the expression, its line named.
    const SceneError e = hexant::test::error_of(loop(300000), animation(), "deep.pov");
    INFO(e.formatted());
    CHECK(e.message().find("nested more than 10000 operations deep") != std::string::npos);
    CHECK(e.formatted().find("deep.pov:3:") != std::string::npos);
    // Just under the limit it reads (and hexant renders it, with a 1 MB
    // stack too: README "Nesting").
    CHECK(read(loop(hexant::runtime::kMaxTimeFunctionDepth - 10)) == "");
}

TEST_CASE("objects built up too deep are an error where they are made, not a crash",
          "[language][nesting]") {
    const auto loop = [](int n) {
        return "#declare O = sphere { 0, 1 };\n#for (I, 1, " + std::to_string(n) +
               ")\n  #declare O = union { object { O } };\n#end\nobject { O }\n";
    };
    // 15,000 levels overflowed the stack gathering the lights of the scene.
    const SceneError e = hexant::test::error_of(loop(15000), {}, "deep.pov");
    INFO(e.formatted());
    CHECK(e.message().find("objects nested more than 10000 deep") != std::string::npos);
    CHECK(e.formatted().find("deep.pov:3:") != std::string::npos);
    CHECK(read(loop(hexant::runtime::kMaxObjectDepth - 10)) == "");
}

TEST_CASE("a union nested as deep as objects may is built for the render, not a crash",
          "[language][nesting]") {
    // Issue 45: a union built up 7,000 deep in a loop read and checked, and
    // the render's objects overflowed the stack splitting it apart.
    const int depth = hexant::runtime::kMaxObjectDepth - 10;
    const auto scene = hexant::test::scene_of(
        "#declare O = sphere { 0, 1 };\n#for (I, 1, " + std::to_string(depth) +
        ")\n  #declare O = union { object { O } sphere { I * x, 0.5 } };\n#end\nobject { O }\n");
    REQUIRE(scene.objects.size() == 1);
    std::vector<hexant::runtime::IntelligentObjectPtr> built;
    hexant::runtime::make_intelligent_objects(*scene.objects[0], scene.default_texture, built);
    // Split apart: every sphere on its own, in the order written.
    CHECK(built.size() == std::size_t(depth) + 1);
}
