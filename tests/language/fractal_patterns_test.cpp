// The fractal patterns (runtime/texture/pattern/kinds/mandel.hpp, julia.hpp,
// magnet.hpp): how the language reads them and their values against POV-Ray
// 3.7's. The values are what POV-Ray 3.7.0.10 printed with eval_pigment
// (functions.inc) at the same points, through a black-to-white map (POV-Ray
// keeps a colour in single precision: hence the tolerance).
#include <sstream>
#include <string>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "runtime/texture/pattern/kinds.hpp"
#include "runtime/texture/texture_evaluator.hpp"
#include "scene_text.hpp"

namespace rt = hexant::runtime;
namespace pt = hexant::runtime::pattern;

namespace {

rt::SceneDescription read(const std::string& text, std::string* messages_out = nullptr) {
    hexant::language::ParseOptions options = hexant::test::animation();
    std::ostringstream messages;
    options.messages = &messages;
    auto scene = hexant::language::parse_scene_text(text, "test.pov", options);
    if (messages_out) *messages_out = messages.str();
    return scene;
}

double grey_at(const rt::SceneDescription& scene, std::size_t i, const glm::dvec3& point) {
    REQUIRE(scene.objects.at(i)->texture);
    const rt::TextureEvaluator evaluator(*scene.objects[i]->texture, std::nullopt);
    rt::TextureSample sample;
    evaluator.sample(point, {0.0, 0.0}, 0.0, {0.0, 0.0, -1.0}, sample);
    double c = 0.0;
    for (const auto& plain : sample.plains)
        c += plain.weight * sample.layers[plain.first].material.colour.r;
    return c;
}

const pt::Pattern& pigment_pattern(const rt::SceneDescription& scene, std::size_t i) {
    REQUIRE(scene.objects.at(i)->texture);
    return scene.objects[i]->texture->pigment.patterned;
}

}  // namespace

TEST_CASE("the fractal patterns' values are POV-Ray 3.7's", "[language][pattern][fractal]") {
    const auto scene = read(R"(
#declare G = color_map { [0 rgb 0] [1 rgb 1] }
#declare F = finish { ambient 1 diffuse 0 }
sphere { 0, 1 pigment { mandel 30 exterior 6, 0.2 interior 1, 1 color_map { G } } finish { F } }
sphere { 0, 1 pigment { mandel 12 exponent 7 exterior 2, 0.25 interior 6, 0.5 color_map { G } } finish { F } }
sphere { 0, 1 pigment { julia <0.353, 0.288>, 30 exponent 3 exterior 8, 3 interior 4, 2 color_map { G } } finish { F } }
sphere { 0, 1 pigment { julia <-0.6, 0.4>, 20 exponent 5 exterior 7, 4 interior 5, 2 color_map { G } } finish { F } }
sphere { 0, 1 pigment { magnet 1 mandel 20 exterior 3, 0.3 interior 2, 1 color_map { G } } finish { F } }
sphere { 0, 1 pigment { magnet 2 mandel 20 exterior 4, 0.1 interior 3, 1 color_map { G } } finish { F } }
sphere { 0, 1 pigment { magnet 1 julia <1.6, 0.4>, 20 exterior 0, 0.7 interior 1, 1 color_map { G } } finish { F } }
sphere { 0, 1 pigment { magnet 2 julia <1.2, 0.3>, 20 exterior 1, 1 interior 0, 0.4 color_map { G } } finish { F } }
)");
    const glm::dvec3 points[] = {{0.25, 0.5, 0}, {-1.3, 0.2, 0}, {-0.1, 0.7, 0.3}, {1.9, -0.4, 0}};
    // POV-Ray's, pigment by pigment, point by point.
    const double pov[8][4] = {
        {0.13374477624893188, 0.41659575700759888, 0.09219544380903244, 0.13680836558341980},
        {0.19835953414440155, 0.85539996623992920, 0.22043958306312561, 0.54532867670059204},
        {0.15977741777896881, 0.0, 0.15977738797664642, 0.0},
        {0.29654106497764587, 0.0, 0.30088925361633301, 0.0},
        {0.14837308228015900, 0.99910676479339600, 0.45820605754852295, 0.52719873189926147},
        {0.38014620542526245, 0.09869222342967987, 0.81030696630477905, 0.09890893846750259},
        {0.69999998807907104, 0.69999998807907104, 0.69999998807907104, 0.69999998807907104},
        {0.40000000596046448, 0.40000000596046448, 0.40000000596046448, 0.10000000149011612}};
    for (std::size_t i = 0; i < 8; ++i)
        for (std::size_t j = 0; j < 4; ++j) {
            INFO("pigment " << i << " at point " << j);
            CHECK(grey_at(scene, i, points[j]) == Approx(pov[i][j]).margin(1e-6));
        }
}

TEST_CASE("the fractal patterns are read as POV-Ray reads them", "[language][pattern][fractal]") {
    using S = pt::kinds::FractalSlots;
    using M = pt::kinds::Magnet;
    std::string messages;
    const auto scene = read(R"(
sphere { 0, 1 pigment { mandel 20.9 exterior 3.7, 0.5 + clock interior 6 2 } }
sphere { 0, 1 pigment { julia <0.3, 0.2 * clock> 10 + 5 * clock exponent 33 } }
sphere { 0, 1 pigment { magnet 2 julia 0.5, 12 } }
sphere { 0, 1 normal { magnet 1 mandel 8, 0.4 exterior 0, 1 } }
sphere { 0, 1 pigment { mandel 10 exponent 34 } }
)",
                            &messages);
    const pt::Pattern& mandel = pigment_pattern(scene, 0);
    CHECK(mandel.number[S::kIterations].constant() == 20.0);
    CHECK(mandel.more[S::kExteriorType].constant() == 3.0);
    CHECK(mandel.more[S::kExteriorFactor](1.0) == Approx(1.5));
    CHECK(mandel.more[S::kInteriorType].constant() == 6.0);
    CHECK(mandel.more[S::kInteriorFactor].constant() == 2.0);
    CHECK(mandel.number[pt::kinds::Mandel::kExponent].constant() == 2.0);
    const pt::Pattern& julia = pigment_pattern(scene, 1);
    CHECK(julia.vector.c[0].constant() == 0.3);
    CHECK(julia.vector.c[1](1.0) == Approx(0.2));
    CHECK(julia.number[S::kIterations](0.5) == 12.0);
    CHECK(julia.number[pt::kinds::Julia::kExponent].constant() == 33.0);
    // The defaults: exterior 1, 1 and interior 0, 1.
    CHECK(julia.more[S::kExteriorType].constant() == 1.0);
    CHECK(julia.more[S::kInteriorFactor].constant() == 1.0);
    const pt::Pattern& magnet = pigment_pattern(scene, 2);
    CHECK(magnet.number[M::kForm].constant() == M::kTwoJulia);
    CHECK(magnet.vector.c[0].constant() == 0.5);
    CHECK(magnet.vector.c[1].constant() == 0.5);
    REQUIRE(scene.objects.at(3)->texture);
    const rt::Normal& normal = *scene.objects[3]->texture->normal;
    CHECK(normal.patterned->number[M::kForm].constant() == M::kOneMandel);
    CHECK(normal.amount.constant() == Approx(0.4));
    // An exponent outside 2 to 33: POV-Ray's warning, and 2.
    CHECK(pigment_pattern(scene, 4).number[pt::kinds::Mandel::kExponent].constant() == 2.0);
    CHECK(messages.find("exponent is 2 to 33, not 34") != std::string::npos);
}

TEST_CASE("what POV-Ray refuses of the fractal patterns is an error",
          "[language][pattern][fractal]") {
    const auto error = [](const std::string& text, const char* words) {
        const auto e = hexant::test::error_of(text, hexant::test::animation());
        INFO(e.formatted());
        CHECK(e.formatted().find(words) != std::string::npos);
    };
    error("sphere { 0, 1 pigment { mandel 10 exterior 9, 1 } }", "exterior is 0 to 8, not 9");
    error("sphere { 0, 1 pigment { mandel 10 interior 7, 1 } }", "interior is 0 to 6, not 7");
    error("sphere { 0, 1 pigment { bozo exterior 1, 1 } }", "exterior belongs to");
    error("sphere { 0, 1 pigment { magnet 1 mandel 10 exponent 3 } }",
          "exponent belongs to julia or mandel, not to magnet");
    error("sphere { 0, 1 pigment { magnet 3 mandel 10 } }", "magnet's type is 1 or 2");
    error("sphere { 0, 1 pigment { magnet 1 bozo } }", "expected 'mandel' or 'julia'");
    error("sphere { 0, 1 pigment { magnet 1 julia 10 } }", "expected magnet's iterations");
    error("sphere { 0, 1 pigment { mandel 10 exterior 1 } }", "expected the modifier's type");
    error("sphere { 0, 1 pigment { mandel 10 exterior clock, 1 } }", "cannot move with clock");
    error("sphere { 0, 1 pigment { mandel 10 exponent 2 + clock } }", "cannot move with clock");
    error("sphere { 0, 1 pigment { julia 10 } }", "a point <cr, ci> and its iterations");
    error("sphere { 0, 1 pigment { julia <1, 2, 3>, 10 } }", "a <cr, ci> of two numbers");
}
