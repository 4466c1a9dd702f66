// min_extent(OBJECT) and max_extent(OBJECT) (language/object_extent.hpp):
// the corners of an object's box as placed, piecewise in time where parts
// appear and vanish with clock, POV-Ray's +-BOUND_HUGE / 2 for a plane, and
// a clear error where the box would move continuously. The look against
// POV-Ray 3.7 is the pov_reference test's (text/extent.pov).
#include <string>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "runtime/objects/shapes.hpp"
#include "tests/language/scene_text.hpp"

namespace rt = hexant::runtime;
using hexant::test::animation;
using hexant::test::error_of;

namespace {

rt::SceneDescription read(const std::string& text) {
    return hexant::language::parse_scene_text(text, "test.pov", animation());
}

// The centre of the i-th object, a sphere placed at a corner, at time t.
glm::dvec3 centre(const rt::SceneDescription& scene, std::size_t i, double t) {
    return std::get<rt::Sphere>(scene.objects.at(i)->shape).center(t);
}

}  // namespace

TEST_CASE("min_extent and max_extent are the corners of an object's box as placed", "[language]") {
    const auto scene = read(R"(
#declare B = sphere { <1, 2, 3>, 0.5 scale 2 translate x }
#declare R = box { 0, <1, 0.5, 0.25> rotate z * 90 }
sphere { min_extent(B), 0.1 }
sphere { max_extent(B), 0.1 }
sphere { min_extent(R), 0.1 }
sphere { max_extent(R), 0.1 }
)");
    const glm::dvec3 lo = centre(scene, 0, 0.0), hi = centre(scene, 1, 0.0);
    CHECK(lo.x == Approx(2.0).margin(1e-12));
    CHECK(lo.y == Approx(3.0).margin(1e-12));
    CHECK(lo.z == Approx(5.0).margin(1e-12));
    CHECK(hi.x == Approx(4.0).margin(1e-12));
    CHECK(hi.y == Approx(5.0).margin(1e-12));
    CHECK(hi.z == Approx(7.0).margin(1e-12));
    // The box turned a quarter about z: x from -0.5 to 0, y from 0 to 1.
    const glm::dvec3 rlo = centre(scene, 2, 0.0), rhi = centre(scene, 3, 0.0);
    CHECK(rlo.x == Approx(-0.5).margin(1e-12));
    CHECK(rhi.x == Approx(0.0).margin(1e-12));
    CHECK(rlo.y == Approx(0.0).margin(1e-12));
    CHECK(rhi.y == Approx(1.0).margin(1e-12));
}

TEST_CASE("the box of an object whose parts come and go with clock changes with them",
          "[language]") {
    // A second ball exists only before clock 0.5: the union's upper corner
    // is the far ball's then, the near one's after.
    const auto scene = read(R"(
#declare U = union {
  sphere { 0, 1 }
  #if (clock < 0.5) sphere { <5, 0, 0>, 1 } #end
}
sphere { max_extent(U), 0.1 }
)");
    CHECK(centre(scene, 0, 0.25).x == Approx(6.0).margin(1e-12));
    CHECK(centre(scene, 0, 0.75).x == Approx(1.0).margin(1e-12));
    CHECK(centre(scene, 0, 0.75).y == Approx(1.0).margin(1e-12));
}

TEST_CASE("a plane's box is POV-Ray's huge one", "[language]") {
    const auto scene = read("#declare P = plane { y, 0 }\nsphere { min_extent(P), 0.1 }\n");
    CHECK(centre(scene, 0, 0.0) == glm::dvec3(-1e10));
}

TEST_CASE("min_extent of a moving object or of no object is an error naming it", "[language]") {
    CHECK_THAT(
        error_of("#declare M = sphere { 0, 1 translate x * clock }\n#declare V = min_extent(M);\n",
                 animation())
            .formatted(),
        Catch::Contains("min_extent()") && Catch::Contains("move with clock") &&
            Catch::Contains("test.pov:2"));
    CHECK_THAT(error_of("#declare V = max_extent(3);\n").formatted(),
               Catch::Contains("max_extent() takes one object"));
}
