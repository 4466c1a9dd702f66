// average, pigment_pattern and slope (runtime/texture/pattern/kinds/): their
// values through the texture evaluator against POV-Ray 3.7's. The pigments'
// colours are what POV-Ray 3.7.0.10 printed with eval_pigment (functions.inc)
// at the same points; slope's are worked from its slope_pattern (pattern.cpp)
// at given normals, which eval_pigment cannot give (no surface there: 0).
#include <cmath>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "runtime/texture/texture_evaluator.hpp"
#include "scene_text.hpp"

namespace rt = hexant::runtime;

namespace {

rt::SceneDescription read(const std::string& text) {
    hexant::language::ParseOptions options;
    std::ostringstream messages;
    options.messages = &messages;
    return hexant::language::parse_scene_text(text, "test.pov", options);
}

// The colour of object i's texture at `point`, seen with the shading
// normal `normal`.
glm::dvec3 colour_at(const rt::SceneDescription& scene, std::size_t i, const glm::dvec3& point,
                     const glm::dvec3& normal = {0.0, 1.0, 0.0}) {
    REQUIRE(scene.objects.at(i)->texture);
    const rt::TextureEvaluator evaluator(*scene.objects[i]->texture, std::nullopt);
    rt::TextureSample sample;
    evaluator.sample(point, {0.0, 0.0}, 0.0, normal, sample);
    glm::dvec3 c(0.0);
    for (const auto& plain : sample.plains)
        c += plain.weight * sample.layers[plain.first].material.colour;
    return c;
}

const glm::dvec3 kPoints[] = {
    {0.25, 0.5, 0.25}, {1.3, 0.2, 0.7}, {-0.6, 1.7, 2.2}, {0.9, -0.4, -1.1}};

}  // namespace

TEST_CASE("pigment_pattern's value is its pigment's grey, as POV-Ray's", "[language][pattern]") {
    // POV-Ray's values (single precision: 1e-6 covers its rounding of the
    // colours and the grey; a wrong weight moves them by 1e-2 or more).
    const auto scene = read(R"(
        sphere { 0, 1 pigment { pigment_pattern { checker rgb <1, 0, 0>, rgb <0.2, 0.9, 1> }
            color_map { [0 rgb 0] [1 rgb 1] } } }
        sphere { 0, 1 pigment { pigment_pattern { gradient x
            color_map { [0 rgb <0.5, 0, 1>] [1 rgb <1, 1, 0>] } } frequency 2
            color_map { [0 rgb 0] [1 rgb 1] } } })");
    const double checker[] = {0.296999991, 0.703499973, 0.296999991, 0.703499973};
    const double gradient[] = {0.836749971, 0.899100006, 0.023790015, 0.647289991};
    for (int k = 0; k < 4; ++k) {
        INFO("point " << k);
        CHECK(colour_at(scene, 0, kPoints[k]).x == Approx(checker[k]).margin(1e-6));
        CHECK(colour_at(scene, 1, kPoints[k]).x == Approx(gradient[k]).margin(1e-6));
    }
}

TEST_CASE("average weighs its pigment_map's entries as POV-Ray's", "[language][pattern]") {
    // POV-Ray's colours (1e-6: single precision). The entries are read at
    // the average's scaled point; weights 1, 3 and 0.5.
    const auto scene = read(R"(
        sphere { 0, 1 pigment { average pigment_map { [1 rgb <1, 0, 0>]
            [3 gradient x color_map { [0 rgb 0] [1 rgb <0, 1, 1>] }]
            [0.5 checker rgb 1, rgb <0, 0, 0.5>] } scale 2 } })");
    const glm::dvec3 expected[] = {{0.333333343, 0.194444448, 0.194444448},
                                   {0.333333343, 0.544444382, 0.544444382},
                                   {0.333333343, 0.577777743, 0.577777743},
                                   {0.333333343, 0.411111087, 0.411111087}};
    for (int k = 0; k < 4; ++k) {
        INFO("point " << k);
        const glm::dvec3 c = colour_at(scene, 0, kPoints[k]);
        CHECK(c.x == Approx(expected[k].x).margin(1e-6));
        CHECK(c.y == Approx(expected[k].y).margin(1e-6));
        CHECK(c.z == Approx(expected[k].z).margin(1e-6));
    }
}

TEST_CASE("slope reads the shading normal as POV-Ray's slope_pattern", "[language][pattern]") {
    // A grey ramp shows the value. slope y: asin(N . y) from [-90, 90]
    // degrees to [0, 1]; 1 itself is kept 1e-10 under 1. With a range
    // [0.25, 0.75] the value is rescaled and wrapped into [0, 1). With an
    // altitude of twice the slope's length (weights 1/3 and 2/3), the
    // point's height in the pattern's space (scaled by 2) joins in.
    const auto scene = read(R"(
        sphere { 0, 1 pigment { slope y } }
        sphere { 0, 1 pigment { slope { y, 0.25, 0.75 } } }
        sphere { 0, 1 pigment { slope { y altitude y * 2, 0, 4 } scale 2 } }
        sphere { 0, 1 pigment { slope { point_at <0, 10, 0> } } })");
    const glm::dvec3 up(0, 1, 0), side(1, 0, 0);
    const glm::dvec3 tilted = glm::normalize(glm::dvec3(1, 1, 0));  // 45 degrees: 0.75
    CHECK(colour_at(scene, 0, {0, 0, 0}, up).x == 1.0 - 1e-10);
    CHECK(colour_at(scene, 0, {0, 0, 0}, side).x == Approx(0.5).margin(1e-12));
    CHECK(colour_at(scene, 0, {0, 0, 0}, tilted).x == Approx(0.75).margin(1e-12));
    CHECK(colour_at(scene, 0, {0, 0, 0}, -tilted).x == Approx(0.25).margin(1e-12));
    // 30 degrees up: 2/3, rescaled from [0.25, 0.75]: (2/3 - 0.25) / 0.5.
    const glm::dvec3 thirty(std::sqrt(0.75), 0.5, 0.0);
    CHECK(colour_at(scene, 1, {0, 0, 0}, thirty).x == Approx((2.0 / 3 - 0.25) / 0.5).margin(1e-12));
    CHECK(colour_at(scene, 1, {0, 0, 0}, side).x == Approx(0.5).margin(1e-12));
    // slope 0.5 at the side; altitude: the point (0, 2, 0) is y = 1 in
    // pattern space, (1 - 0) / 4 = 0.25: 0.5 / 3 + 0.25 * 2 / 3.
    CHECK(colour_at(scene, 2, {0, 2, 0}, side).x == Approx(0.5 / 3 + 0.5 / 3).margin(1e-12));
    // point_at: the direction from the hit to the point; facing it, 1.
    CHECK(colour_at(scene, 3, {0, 0, 0}, up).x == 1.0 - 1e-10);
    CHECK(colour_at(scene, 3, {0, 0, 0}, side).x == Approx(0.5).margin(1e-12));
}

TEST_CASE("what POV-Ray refuses of average and slope is an error", "[language][pattern]") {
    const auto error = [](const std::string& text, const char* words) {
        const auto e = hexant::test::error_of(text);
        INFO(e.formatted());
        CHECK(e.formatted().find(words) != std::string::npos);
    };
    error("sphere { 0, 1 pigment { average } }", "average needs a pigment_map");
    error("sphere { 0, 1 pigment { average color_map { [0 rgb 0] [1 rgb 1] } } }",
          "a color_map cannot go with average");
    error("sphere { 0, 1 normal { average } }", "average needs a normal_map");
    error("sphere { 0, 1 pigment { slope { 0 altitude 0 } } }", "both of zero length");
    error("sphere { 0, 1 pigment { slope { point_at 1 altitude y } } }",
          "altitude cannot go with point_at");
    error("sphere { 0, 1 pigment { pigment_pattern { bozo } 0.5 } }", "only in a normal");
}
