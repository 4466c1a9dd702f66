// User functions as the language builds them (runtime/time/user_function.hpp):
// calls share what they compute, so functions that call others stay the
// size of their text. (Values against POV-Ray's are in pov_reference.)
#include <string>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "runtime/objects/shapes.hpp"
#include "runtime/time/time_tape.hpp"

namespace rt = hexant::runtime;

TEST_CASE("a chain of functions that each call the last twice stays small",
          "[language][function]") {
    // F(k) = (F(k-1)(x, y, z) + F(k-1)(x, y, z)) / 2: copied at each call,
    // F40 would hold 2^40 copies of F0.
    std::string text =
        "#version 3.7;\n#declare F0 = function(x, y, z) { x * x + y * y + z * z - 1 }\n";
    for (int k = 1; k <= 40; ++k)
        text += "#declare F" + std::to_string(k) + " = function(x, y, z) { (F" +
                std::to_string(k - 1) + "(x, y, z) + F" + std::to_string(k - 1) +
                "(x, y, z)) * 0.5 }\n";
    text += "isosurface { function { F40(x, y, z) } contained_by { box { -2, 2 } } }\n";
    const auto scene = hexant::language::parse_scene_text(text, "chain.pov", {});
    REQUIRE(scene.objects.size() == 1);
    const auto& iso = std::get<rt::Isosurface>(scene.objects[0]->shape);
    const rt::TimeTape tape = rt::TimeTape::compile({*iso.function});
    // Seven operations for F0, two for each link.
    CHECK(tape.size() < 200);
    // The same surface as F0's: the unit sphere.
    const rt::SpaceFunction f(*iso.function);
    CHECK(f.at({1.0, 0.0, 0.0}, 0.0) == Approx(0.0).margin(1e-12));
    CHECK(f.at({0.0, 0.0, 0.0}, 0.0) == Approx(-1.0));
}

TEST_CASE("spline, pigment and pattern functions give their values", "[language][function]") {
    // A spline function is the spline's vector at its argument, a pigment
    // function the pigment's colour by component, a pattern function the
    // pattern's value; each may be called in another function, and a call
    // with numbers is a number. (splinefunction.pov reads all three.)
    const std::string text =
        "#version 3.7;\n"
        "#declare S = function { spline { linear_spline 0, <0, 0, 0> 1, <2, 4, 6> } }\n"
        "#declare P = function { pigment { gradient x color_map { [0 rgb 0] [1 rgb <1, 0.5, "
        "0.25>] } } }\n"
        "#declare Q = function { pattern { gradient x } }\n"
        "#declare G = function { P(x, y, z).green + S(x).z }\n"
        "sphere { 0, S(0.25).y }\n"
        "sphere { 0, P(0.5, 0, 0).blue }\n"
        "sphere { 0, Q(0.75, 3, 0) }\n"
        "sphere { 0, G(0.5, 0, 0) }\n"
        "sphere { 0, P(0.5, 0, 0).gray }\n";
    const auto scene = hexant::language::parse_scene_text(text, "functions.pov", {});
    REQUIRE(scene.objects.size() == 5);
    const auto radius = [&](std::size_t i) {
        const auto& r = std::get<rt::Sphere>(scene.objects[i]->shape).radius;
        REQUIRE(r.is_constant());
        return r.constant();
    };
    CHECK(radius(0) == Approx(1.0));
    CHECK(radius(1) == Approx(0.125));
    CHECK(radius(2) == Approx(0.75));
    CHECK(radius(3) == Approx(0.25 + 3.0));
    CHECK(radius(4) == Approx(0.297 * 0.5 + 0.589 * 0.25 + 0.114 * 0.125));
}

TEST_CASE("an isosurface of a pigment function reads its max_gradient", "[language][function]") {
    // A pigment function has no interval bound: the isosurface is searched
    // as POV-Ray searches it, and max_gradient (default 1.1) is its slope.
    const std::string head =
        "#version 3.7;\n"
        "#declare P = function { pigment { bozo color_map { [0 rgb 0] [1 rgb 1] } } }\n";
    const auto read = [&](const std::string& setting) {
        return hexant::language::parse_scene_text(
            head + "isosurface { function { y - P(x, 0, z).red } " + setting + " }\n", "iso.pov",
            {});
    };
    const auto scene = read("max_gradient 3.5");
    REQUIRE(scene.objects.size() == 1);
    const auto& iso = std::get<rt::Isosurface>(scene.objects[0]->shape);
    CHECK(iso.max_gradient == 3.5);
    CHECK(rt::SpaceFunction(*iso.function).unbounded_part() != nullptr);
    CHECK(std::get<rt::Isosurface>(read("").objects[0]->shape).max_gradient == 1.1);
    CHECK_THROWS_WITH(read("max_gradient 0"), Catch::Contains("max_gradient must be a positive"));
    CHECK_THROWS_WITH(read("max_gradient -2"), Catch::Contains("iso.pov:3"));
}
