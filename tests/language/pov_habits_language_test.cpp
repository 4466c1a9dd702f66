// How POV-Ray 3.7 reads what its own include files and scenes write: a
// macro's arguments without a comma after an object (shapes.pov's
// Align_Object(Center_Object(O, x) -y, 0)), and a #while writing a shape's
// arguments after a comma (grenadine's lemon.inc prisms).
#include <string>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "scene_text.hpp"

using hexant::test::check_error_at;
using hexant::test::scene_of;

namespace rt = hexant::runtime;

TEST_CASE("a macro's arguments may leave out their commas, an object's value ending there",
          "[language]") {
    const auto scene = scene_of(R"(
#macro Place(O, V, W) object { O translate V + W } #end
Place(sphere { 0, 1 } -y, <1, 0, 0>)
)");
    REQUIRE(scene.objects.size() == 1);
    const auto m = scene.objects[0]->transform.matrix_at(0.0);
    CHECK(m[3][0] == 1.0);
    CHECK(m[3][1] == -1.0);
    // Numbers still take + and -: one argument here, too few.
    check_error_at("#macro M(A, B) sphere { 0, A + B } #end\nM(1 -2)", "takes 2 arguments", 2);
}

TEST_CASE("a #while after a comma writes a shape's arguments", "[language]") {
    const auto scene = scene_of(R"(
#declare P = array[4] { <0, 0>, <1, 0>, <1, 1>, <0, 0> }
#declare J = 0;
prism { linear_sweep linear_spline 0, 1, 4,
  #while (J < 4) #declare Q = P[J]; Q #declare J = J + 1; #end
  translate x
}
)");
    REQUIRE(scene.objects.size() == 1);
    CHECK(scene.objects[0]->transform.matrix_at(0.0)[3][0] == 1.0);
}
