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
