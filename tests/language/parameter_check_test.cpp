// Scene parameters the renderer cannot use are errors at their place, with
// the instant when they depend on clock (runtime/objects/parameter_check.hpp), and
// parameters that only look risky are not.
#include <sstream>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "scene_text.hpp"

using hexant::language::ParseOptions;
using hexant::language::SceneError;
using hexant::test::read_error;

namespace {

ParseOptions animation() {
    ParseOptions options;
    options.animation.final_frame = 11;  // clock 0, 0.1, ... 1
    return options;
}

// The message of the error `text` gives, at line:column.
std::string message_at(const std::string& text, std::size_t line, std::size_t column,
                       ParseOptions options = {}) {
    const auto e = read_error(text, options);
    REQUIRE(e);
    INFO(e->formatted());
    CHECK(e->places().front().line == line);
    CHECK(e->places().front().column == column);
    return e->message();
}

}  // namespace

TEST_CASE("NaN and infinite shape parameters are errors at the shape", "[parameters]") {
    using Catch::Contains;
    CHECK_THAT(message_at("sphere { 0, sqrt(-1) }", 1, 1), Contains("the sphere's radius is NaN"));
    CHECK_THAT(message_at("\n  box { <0, 0, 0>, <1, sqrt(-1), 1> }", 2, 3),
               Contains("the box's second corner is NaN"));
    CHECK_THAT(message_at("torus { 1, 1e300 * 1e300 }", 1, 1),
               Contains("the torus's minor radius is infinite"));
    CHECK_THAT(message_at("union {\n  sphere { 0, 1 }\n  cylinder { 0, y, ln(0) }\n}", 3, 3),
               Contains("the cylinder's radius is infinite"));
}

TEST_CASE("NaN, infinite and singular transforms are errors", "[parameters]") {
    using Catch::Contains;
    CHECK_THAT(message_at("sphere { 0, 1 translate <1e300 * 1e300, 0, 0> }", 1, 1),
               Contains("the sphere's translate is infinite"));
    CHECK_THAT(
        message_at("sphere { 0, 1 matrix <1, 0, 0, 0, sqrt(-1), 0, 0, 0, 1, 0, 0, 0> }", 1, 1),
        Contains("the sphere's matrix is NaN"));
    CHECK_THAT(message_at("sphere { 0, 1 matrix <1, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0> }", 1, 1),
               Contains("transform is singular"));
    CHECK_THAT(message_at("sphere { 0, 1 scale 1e200 scale 1e200 }", 1, 1),
               Contains("transform is infinite"));
    // scale 0 stays POV-Ray's warning and 1.
    CHECK_FALSE(read_error("sphere { 0, 1 scale <0, 1, 1> }"));
}

TEST_CASE("NaN and infinite colours, finishes and lights are errors", "[parameters]") {
    using Catch::Contains;
    CHECK_THAT(message_at("sphere { 0, 1 pigment { rgb <1, sqrt(-2), 0> } }", 1, 1),
               Contains("pigment's colour is NaN"));
    CHECK_THAT(message_at("sphere { 0, 1 finish { phong 1e308 * 10 } }", 1, 1),
               Contains("finish's phong is infinite"));
    // (Every scalar of a finish, a colour ambient's channels and crand
    // among them: Finish::scalars.)
    CHECK_THAT(message_at("sphere { 0, 1 finish { crand sqrt(-1) } }", 1, 1),
               Contains("finish's crand is NaN"));
    CHECK_THAT(message_at("sphere { 0, 1 finish { ambient rgb <0, 1e308 * 10, 0> } }", 1, 1),
               Contains("finish's ambient is infinite"));
    CHECK_THAT(message_at("\nlight_source { <0, 5, 0>, rgb 1e300 * 1e300 }", 2, 1),
               Contains("the light's colour is infinite"));
    // The #default texture, which the objects that take it do not check.
    CHECK_THAT(message_at("#default { finish { ambient 1 / (clock - 0.5) } }\nsphere { 0, 1 }", 1,
                          12, animation()),
               Contains("the #default finish's ambient is infinite at clock = 0.5"));
    CHECK_THAT(message_at("#default { pigment { rgb sqrt(-1) } }", 1, 12),
               Contains("the #default pigment's colour is NaN"));
}

TEST_CASE("a camera with no direction, or looking at its own location, is an error",
          "[parameters]") {
    using Catch::Contains;
    CHECK_THAT(message_at("camera { direction 0 }", 1, 1),
               Contains("direction is the zero vector"));
    CHECK_THAT(message_at("camera { location <1, 2, 3> look_at <1, 2, 3> }", 1, 1),
               Contains("look_at is its location"));
    CHECK_THAT(message_at("camera { location <0, 0, sqrt(-1)> }", 1, 1),
               Contains("the camera's location is NaN"));
    // A camera naming its type (the fuzzer's find: its item was looked up in
    // the table of vector names, past its end) is checked as its kind is.
    CHECK_THAT(message_at("camera { perspective location <0, 0, sqrt(-1)> }", 1, 1),
               Contains("the camera's location is NaN"));
    // Only at some instant: the look_at passes through the camera at clock 0.5.
    CHECK_THAT(message_at("camera { location <0, 0, -5> look_at <0, 0, -10 + 10 * clock> }", 1, 1,
                          animation()),
               Contains("look_at is its location at clock = 0.5"));
}

TEST_CASE("a parameter of clock is checked over the animation's time, at the first instant",
          "[parameters]") {
    using Catch::Contains;
    CHECK_THAT(message_at("sphere { 0, sqrt(0.5 - clock) }", 1, 1, animation()),
               Contains("the sphere's radius is NaN (not a number) at clock = 0.5"));
    CHECK_THAT(message_at("sphere { 0, 1 translate x / (clock - 0.25) }", 1, 1, animation()),
               Contains("translate is infinite at clock = 0.25"));
    // Outside the animation's time it is no error: clock runs 0 to 1.1 here (the
    // last frame's shutter closes at 1.1).
    CHECK_FALSE(read_error("sphere { 0, sqrt(2 - clock) }", animation()));
    // Intervals that only might be infinite: each point is 1.
    CHECK_FALSE(read_error("sphere { 0, 1 / (clock - clock + 1) }", animation()));
    // A declared object that is never used is not checked (nor costs anything).
    CHECK_FALSE(read_error("#declare B = sphere { 0, sqrt(-1) }"));
}

TEST_CASE("a --declare number beyond the doubles is an error, not an infinity", "[parameters]") {
    ParseOptions options;
    options.declares = {{"Far", "<1, 1e999, 0>"}};
    const auto e = read_error("sphere { 0, 1 }", options);
    REQUIRE(e);
    CHECK_THAT(e->message(), Catch::Contains("1e999"));
    options.declares = {{"Near", "1e300"}};
    CHECK_FALSE(read_error("sphere { 0, 1 }", options));
}
