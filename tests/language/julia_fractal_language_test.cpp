// julia_fractal { } as the language reads it (runtime/objects/julia_fractal/,
// the grammar's julia_block): POV-Ray 3.7's words and settings
// (Parse_Julia_Fractal), its defaults, time functions, and its refusals.
#include <algorithm>
#include <string>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "runtime/objects/shapes.hpp"
#include "tests/language/scene_text.hpp"

namespace rt = hexant::runtime;
using hexant::test::error_of;
using rt::geometry::JuliaAlgebra;
using rt::geometry::JuliaFunction;

namespace {

rt::JuliaFractal julia_of(const std::string& text) {
    const auto scene = hexant::language::parse_scene_text(text, "t.pov", {});
    REQUIRE(scene.objects.size() == 1);
    return std::get<rt::JuliaFractal>(scene.objects[0]->shape);
}

bool says(const std::string& scene, const std::string& part) {
    const std::string message = error_of(scene).what();
    INFO(message);
    return message.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE("julia_fractal reads POV-Ray's words and settings", "[language][julia_fractal]") {
    const auto j = julia_of(
        "julia_fractal { <0.1, 0.2, 0.3, 0.4> hypercomplex pwr(2, -0.5) max_iteration 7.9 "
        "precision 30 slice <0, 0, 1, 1>, 0.25 pigment { rgb 1 } translate x }");
    CHECK(j.parameter[3].constant() == 0.4);
    CHECK(j.algebra == JuliaAlgebra::hypercomplex);
    CHECK(j.function == JuliaFunction::pwr);
    CHECK(j.exponent[1].constant() == -0.5);
    CHECK(j.iterations == 7);  // floor, as POV-Ray
    CHECK(j.precision == 30.0);
    CHECK(j.slice[2].constant() == 1.0);
    CHECK(j.slice_distance.constant() == 0.25);
    // POV-Ray's defaults; a float is all four components, a 3-vector gets t = 0.
    const auto d = julia_of("julia_fractal { 0.5 }");
    CHECK(d.algebra == JuliaAlgebra::quaternion);
    CHECK(d.function == JuliaFunction::sqr);
    CHECK(d.iterations == 20);
    CHECK(d.parameter[3].constant() == 0.5);
    CHECK(julia_of("julia_fractal { <1, 2, 3> max_iteration -3 }").parameter[3].constant() == 0.0);
    CHECK(julia_of("julia_fractal { <1, 2, 3> max_iteration -3 }").iterations == 1);
    for (const char* word : {"exp", "ln", "sin", "asin", "sinh", "asinh", "cos", "acos", "cosh",
                             "acosh", "tan", "atan", "tanh", "atanh", "reciprocal", "cube"})
        CHECK(rt::JuliaFractal::function_word(
                  julia_of(std::string("julia_fractal { <0, 0, 0, 0> hypercomplex ") + word + " }")
                      .function) == word);
}

TEST_CASE("a julia_fractal's parameter and slice may move with clock",
          "[language][julia_fractal]") {
    hexant::language::ParseOptions options;
    options.animation.initial_frame = 1;
    options.animation.final_frame = 2;
    const auto scene = hexant::language::parse_scene_text(
        "julia_fractal { <0.1 * clock, 0, 0, 0> slice <0, 0, 0, 1>, clock }", "t.pov", options);
    const auto& j = std::get<rt::JuliaFractal>(scene.objects[0]->shape);
    CHECK(j.parameter[0].depends_on_time());
    CHECK(j.slice_distance.depends_on_time());
    const auto moving = scene.objects[0]->timed_parameters();
    CHECK(std::find(moving.begin(), moving.end(), "c.x") != moving.end());
}

TEST_CASE("a julia_fractal refuses what POV-Ray refuses", "[language][julia_fractal]") {
    CHECK(says("julia_fractal { <0, 0, 0, 0> quaternion sin }", "only sqr and cube"));
    CHECK(says("julia_fractal { <0, 0, 0, 0> slice <0, 0, 0, 0>, 1 }", "slice vector is zero"));
    CHECK(says("julia_fractal { <0, 0, 0, 0> slice <1, 0, 0, 0>, 1 }", "zero t component"));
    CHECK(says("julia_fractal { rgbft <0, 0, 0, 0, 0> }", "4D vector"));
    CHECK(says("julia_fractal { <0, 0, 0, 0> pwr(1) }", "expected ','"));
}
