// bicubic_patch { } as the language reads it (runtime/objects/bicubic_patch/,
// the grammar's bicubic_block): POV-Ray 3.7's words before the points
// (Parse_Bicubic_Patch), its defaults, commas, time functions, and clear
// errors, each naming its place, for what it cannot render.
#include <algorithm>
#include <cstddef>
#include <string>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "runtime/objects/shapes.hpp"
#include "tests/language/scene_text.hpp"

namespace rt = hexant::runtime;
using hexant::test::error_of;

namespace {

// Sixteen points, row by row, commas as given.
std::string points(const char* comma = ", ", int count = 16) {
    std::string out;
    for (int k = 0; k < count; ++k)
        out += (k ? comma : "") + std::string("<") + std::to_string(k / 4) + ", " +
               std::to_string(k % 4) + ", " + std::to_string(k % 3) + ">";
    return out;
}

rt::BicubicPatch patch_of(const std::string& text) {
    const auto scene = hexant::language::parse_scene_text(text, "t.pov", {});
    REQUIRE(scene.objects.size() == 1);
    return std::get<rt::BicubicPatch>(scene.objects[0]->shape);
}

}  // namespace

TEST_CASE("bicubic_patch reads POV-Ray's words, points and uv_vectors",
          "[language][bicubic_patch]") {
    const auto p = patch_of(
        "bicubic_patch { type 1 flatness 0.05 u_steps 3.9 v_steps 2 "
        "accuracy 0.001 uv_vectors <0, 0> <2, 0>, <2, 2> <0, 2>, " +
        points() + " pigment { rgb 1 } translate x }");
    CHECK(p.type == 1);
    CHECK(p.flatness == 0.05);
    CHECK(p.u_steps == 3);  // (int), as POV-Ray
    CHECK(p.v_steps == 2);
    CHECK(p.uv_corners[2].c[1].constant() == 2.0);
    CHECK(p.points[6].c[0].constant() == 1.0);
    CHECK(p.points[6].c[1].constant() == 2.0);
    CHECK(p.points[15].c[2].constant() == 0.0);
    // POV-Ray's defaults; the words in any order; commas left out
    // (teapot.inc), or one after the words (primitiv.pov).
    const auto d = patch_of("bicubic_patch { v_steps 1 type 0 " + points(" ") + " }");
    CHECK(d.type == 0);
    CHECK(d.flatness == 0.0);
    CHECK(d.u_steps == 0);
    CHECK(d.v_steps == 1);
    CHECK(d.uv_corners[1].c[0].constant() == 1.0);
    CHECK(patch_of("bicubic_patch { type 1 u_steps 4, " + points() + " }").u_steps == 4);
    // Declared points, and the object's modifiers after them.
    const auto named = patch_of("#declare A = <1, 2, 3>;\nbicubic_patch { type 1 A, " +
                                points(", ", 15) + " scale 2 }");
    CHECK(named.points[0].c[2].constant() == 3.0);
}

TEST_CASE("a bicubic_patch's points may move with clock", "[language][bicubic_patch]") {
    hexant::language::ParseOptions options;
    options.animation.initial_frame = 1;
    options.animation.final_frame = 2;
    const auto scene = hexant::language::parse_scene_text(
        "bicubic_patch { type 0 <clock, 0, 0> " + points(" ", 15) + " }", "t.pov", options);
    const auto& p = std::get<rt::BicubicPatch>(scene.objects[0]->shape);
    CHECK(p.points[0].depends_on_time());
    const auto moving = scene.objects[0]->timed_parameters();
    CHECK(std::find(moving.begin(), moving.end(), "p00") != moving.end());
}

TEST_CASE("a bicubic_patch's bad input is a clear error at its place",
          "[language][bicubic_patch]") {
    const auto check = [](const std::string& text, const std::string& says, std::size_t line,
                          std::size_t column) {
        const auto e = error_of(text);
        INFO(e.formatted());
        CHECK(e.message().find(says) != std::string::npos);
        REQUIRE_FALSE(e.places().empty());
        CHECK(e.places()[0].line == line);
        CHECK(e.places()[0].column == column);
    };
    // Too few and too many points: counted where they start.
    check("sphere { 0, 1 }\nbicubic_patch { type 1\n  " + points(", ", 15) +
              "\n  pigment { rgb 1 } }",
          "16 control points (4 rows of 4), but 15 were given", 3, 3);
    check("bicubic_patch { type 1 " + points(", ", 17) + " }", "but 17 were given", 1, 24);
    // A type POV-Ray 3.7 no longer renders, or never did.
    check("bicubic_patch {\n  type 2 " + points() + " }", "type is 0 or 1, not 2", 2, 3);
    check("bicubic_patch { type -1 " + points() + " }", "type is 0 or 1, not -1", 1, 17);
    check("bicubic_patch { " + points() + " }", "needs its type", 1, 17);
    // Steps: none below 0, none beyond hexant's 16.
    check("bicubic_patch { type 0\n\n u_steps -1 " + points() + " }",
          "u_steps is a whole number from 0 to 16, not -1", 3, 2);
    check("bicubic_patch { type 0 v_steps 40 " + points() + " }",
          "v_steps is a whole number from 0 to 16, not 40", 1, 24);
    // A point that is not a vector; a comma after the last point (POV-Ray
    // 3.7.0 refuses it too).
    check("bicubic_patch { type 0 " + points(", ", 15) + ", \"p\" }", "control point 16", 1, 24);
    check("bicubic_patch { type 0 " + points() + ", pigment { rgb 1 } }", "expected a parameter", 1,
          24 + points().size() + 2);
}
