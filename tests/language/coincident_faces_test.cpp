// Coincident flat faces (runtime/scene/coincident_faces.hpp): warned at the
// pair's places where a ray can tell the two apart, and nowhere else. The
// scenes are the kinds met in POV-Ray's distribution (lights/shadows: a
// glass box standing in the floor's plane; advanced/pawns: squares flush
// with the board; Tango: a difference cut flush).
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

#include "tests/language/scene_text.hpp"

namespace {

using hexant::test::read_error;
using hexant::test::scene_of;

// The coincident-faces warnings reading `text` gives.
std::vector<std::string> warned(const std::string& text,
                                hexant::language::ParseOptions options = {}) {
    std::vector<std::string> out;
    for (const auto& w : scene_of(text, std::move(options)).warnings)
        if (w.find("coincident") != std::string::npos) out.push_back(w);
    return out;
}

const std::string kGlass = "pigment { rgbf <1, 1, 1, 0.9> } interior { ior 1.3 }";

}  // namespace

TEST_CASE("a glass box standing in the floor's plane is warned at both places",
          "[language][coincident]") {
    const auto w = warned(
        "plane { y, 0 pigment { rgb 1 } }\n"
        "box { <-1, 0, -1>, <1, 2, 1> " +
        kGlass + " rotate 40*y }\n");
    REQUIRE(w.size() == 1);
    CHECK(w[0].rfind("test.pov:1:1: warning: this plane and the box at test.pov:2:1", 0) == 0);
    // A hair above the floor (a thousandth of its size) it is not.
    CHECK(warned("plane { y, 0 pigment { rgb 1 } }\n"
                 "box { <-1, 0.001, -1>, <1, 2, 1> " +
                 kGlass + " }\n")
              .empty());
}

TEST_CASE("opaque objects that face each other hide the coincidence", "[language][coincident]") {
    // A box on the floor, boxes stacked and side by side: each face is
    // behind the other object, whichever the ray takes.
    CHECK(warned("plane { y, 0 pigment { rgb 1 } }\n"
                 "box { <-1, 0, -1>, <1, 2, 1> pigment { rgb x } }\n"
                 "box { <-1, 2, -1>, <1, 3, 1> pigment { rgb y } }\n"
                 "box { <1, 0, -1>, <2, 2, 1> pigment { checker rgb 1, rgb 0 } }\n")
              .empty());
    // A texture_map of opaque textures is opaque too: a cylinder's cap on
    // a cone's base (the axis arrows of POV-Ray's templates).
    CHECK(warned("cylinder { 0, y, 0.05 texture { checker texture { pigment { rgb 1 } } "
                 "texture { pigment { rgb 0 } } } }\n"
                 "cone { y, 0.2, 2*y, 0 pigment { rgb x } }\n")
              .empty());
    // With a clear one among them the face behind shows through.
    CHECK(warned("cylinder { 0, y, 0.05 pigment { rgbt 0.5 } }\n"
                 "cone { y, 0.2, 2*y, 0 pigment { rgb x } }\n")
              .size() == 1);
}

TEST_CASE("faces that face the same way are warned, unless one texture covers both",
          "[language][coincident]") {
    // A board's square flush with the board (pawns).
    const std::string square = "box { <0, -1, 0>, <1, 0, 1> pigment { rgb x } }\n";
    const std::string board = "box { <-4, -0.5, -4>, <4, 0, 4> pigment { rgb y } }\n";
    CHECK(warned(square + board).size() == 1);
    // In one union under one texture, nothing tells them apart.
    CHECK(warned("union { box { <0, -1, 0>, <1, 0, 1> } box { <-4, -0.5, -4>, <4, 0, 4> } "
                 "pigment { rgb y } }\n")
              .empty());
    // A disc lies on the floor: it is seen from both sides.
    CHECK(warned("plane { y, 0 pigment { rgb 1 } }\n"
                 "disc { 0, -y, 1 pigment { rgb x } }\n")
              .size() == 1);
}

TEST_CASE("a difference cut flush is warned, a mitred frame is not", "[language][coincident]") {
    // The subtracted box's top is the body's top (Tango's cut).
    CHECK(warned("difference { box { -1, 1 } box { <-0.5, 0, -0.5>, <0.5, 1, 0.5> } "
                 "pigment { rgb 1 } }\n")
              .size() == 1);
    // Rails cut by planes at 45 degrees meet at their mitres only: their
    // faces touch along a line, and the mitres face each other.
    CHECK(warned("#declare Rail = intersection {\n"
                 "  box { <-10, -0.25, -1>, <10, 0.25, 1> }\n"
                 "  plane { -x, 0 rotate 45*y translate -9*x }\n"
                 "  plane { x, 0 rotate -45*y translate 9*x }\n"
                 "  translate <0, -0.25, -9> pigment { rgb 1 } }\n"
                 "union { object { Rail } object { Rail rotate 90*y }\n"
                 "        object { Rail rotate 180*y } object { Rail rotate 270*y } }\n")
              .empty());
    // A face of an intersection's member outside the other members is
    // not there: a cylinder's caps beyond the box it is cut by.
    CHECK(warned("#declare T = intersection { box { -1, 1 } cylinder { -1.15*y, 1.15*y, 1.3 } "
                 "pigment { rgb 1 } }\n"
                 "object { T } object { T translate 2.1*x }\n")
              .empty());
}

TEST_CASE("the coincidence test does not depend on the scene's scale or turn",
          "[language][coincident]") {
    for (const char* size : {"1e-6", "1", "1e6"})
        for (const char* turn : {"0", "33", "90"}) {
            const std::string wrap = std::string(" rotate ") + turn + "*y scale " + size + " }\n";
            INFO(size << " " << turn);
            CHECK(warned("union { plane { y, 0 pigment { rgb 1 } }\n"
                         "box { <-1, 0, -1>, <1, 2, 1> " +
                         kGlass + " rotate 17*y translate <3, 0, 5> }" + wrap)
                      .size() == 1);
            CHECK(warned("union { plane { y, 0 pigment { rgb 1 } }\n"
                         "box { <-1, 1e-6, -1>, <1, 2, 1> " +
                         kGlass + " rotate 17*y translate <3, 0, 5> }" + wrap)
                      .empty());
        }
}

TEST_CASE("the coincidence test holds far from the origin, beside vast faces and at 45 degrees",
          "[language][coincident]") {
    // (Found by a fresh user.) Small boxes far away were taken for slivers.
    CHECK(warned("box { 0, 0.01 pigment { rgb x } translate 500*x }\n"
                 "box { 0, 0.01 pigment { rgb y } translate 500*x }\n")
              .size() == 1);
    // A vast floor's size did not belong in a small box's slack.
    CHECK(warned("box { <-1e7, -1, -1e7>, <1e7, 0, 1e7> pigment { rgb 1 } }\n"
                 "box { <-1, 0.01, -1>, <1, 2, 1> " +
                 kGlass + " }\n")
              .empty());
    // Two writings of one plane at 45 degrees took opposite signs.
    CHECK(warned("plane { x, 0 pigment { rgb 1 } rotate 45*y }\n"
                 "plane { -z, 0 pigment { rgb x } rotate -45*y }\n")
              .size() == 1);
    CHECK(warned("plane { -x, 0 rotate -45*z pigment { rgb 1 } }\n"
                 "box { <-1, 0, -1>, <1, 2, 1> " +
                 kGlass + " rotate 45*z }\n")
              .size() == 1);
}

TEST_CASE("copies of one object are one pair, and many pairs are counted",
          "[language][coincident]") {
    // Forty copies of one box in one place: one warning, naming the copies.
    const auto same = warned("#for (I, 1, 40) box { 0, 1 pigment { rgb x } } #end\n");
    REQUIRE(same.size() == 1);
    CHECK(same[0].find("two copies of this box") != std::string::npos);
    // Thirty distinct pairs: the first sixteen named, the rest counted.
    std::string many;
    for (int i = 0; i < 30; ++i) {
        const std::string at = "translate " + std::to_string(3 * i) + "*x ";
        many +=
            "box { 0, 1 pigment { rgb x } " + at + "}\nbox { 0, 1 pigment { rgb y } " + at + "}\n";
    }
    const auto w = warned(many);
    REQUIRE(w.size() == 17);
    CHECK(w.back().find("14 more pairs") != std::string::npos);
}

TEST_CASE("moving objects and ones in other pieces of time are not compared",
          "[language][coincident]") {
    CHECK(warned("plane { y, 0 pigment { rgb 1 } }\n"
                 "box { <-1, 0, -1>, <1, 2, 1> " +
                     kGlass + " translate clock*x }\n",
                 hexant::test::animation())
              .empty());
    // Two boxes in one place, each in its own half of the animation.
    const std::string halves =
        "#if (clock < 0.5) box { 0, 1 pigment { rgb x } } #end\n"
        "#if (clock >= 0.5) box { 0, 1 pigment { rgb y } } #end\n";
    CHECK(warned(halves, hexant::test::animation()).empty());
}

TEST_CASE("under strict reading coincident faces are refused at the first place",
          "[language][coincident]") {
    hexant::language::ParseOptions options;
    options.strict = true;
    const auto e =
        read_error("box { 0, 1 pigment { rgb x } }\nbox { 0, 1 pigment { rgb y } }\n", options);
    REQUIRE(e);
    CHECK(e->places().front().line == 1);
    CHECK(e->formatted().find("coincident surfaces") != std::string::npos);
}
