// The pattern kinds' registry (runtime/texture/pattern/kinds.hpp): what the
// grammar derives from it and what each kind's file declares reach the
// texture evaluator's Kind, and the language sets a kind's own settings by
// their names. The defaults are POV-Ray 3.7's (Parse_Pattern, pigment.cpp),
// as the registry held them before each kind had its file.
#include <algorithm>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "runtime/texture/pattern/kinds.hpp"
#include "scene_text.hpp"

namespace rt = hexant::runtime;
namespace pt = hexant::runtime::pattern;

namespace {

// Read as an animation, so that clock is a function of time.
rt::SceneDescription read(const std::string& text) {
    hexant::language::ParseOptions options = hexant::test::animation();
    std::ostringstream messages;
    options.messages = &messages;
    return hexant::language::parse_scene_text(text, "test.pov", options);
}

const pt::Pattern& pigment_pattern(const rt::SceneDescription& scene, std::size_t i) {
    REQUIRE(scene.objects.at(i)->texture);
    return scene.objects[i]->texture->pigment.patterned;
}

}  // namespace

TEST_CASE("the grammar's pattern words are the registered kinds' keywords", "[pattern][registry]") {
    using Words = pt::PatternWords<pt::PatternKinds>;
    std::vector<std::string_view> names;
    for (const pt::Kind* k : pt::all_kinds()) names.push_back(k->name);
    REQUIRE(names.size() == Words::keywords.size());
    CHECK(std::equal(names.begin(), names.end(), Words::keywords.begin()));
    for (const std::string_view name : names) {
        const pt::Kind* k = pt::find_kind(name);
        REQUIRE(k != nullptr);
        CHECK(k->name == name);
        CHECK(k->value != nullptr);
    }
    CHECK(pt::find_kind("no_such_pattern") == nullptr);
    // The kinds' own settings, each once.
    for (const char* s :
         {"agate_turb", "brick_size", "control0", "control1", "form", "metric", "mortar", "offset"})
        CHECK(std::binary_search(Words::settings.begin(), Words::settings.end(),
                                 std::string_view(s)));
    CHECK(std::adjacent_find(Words::settings.begin(), Words::settings.end()) ==
          Words::settings.end());
}

TEST_CASE("each kind's file gives POV-Ray's defaults", "[pattern][registry]") {
    const pt::Kind& brick = *pt::find_kind("brick");
    CHECK(brick.number[0] == 0.5 - 2.0e-10);
    CHECK(brick.vector == glm::dvec3(8.0, 3.0, 4.5));
    CHECK(brick.argument == pt::Kind::Argument::Colours);
    CHECK(brick.colours == 2);
    CHECK_FALSE(brick.frequency);
    REQUIRE(brick.default_map.size() == 2);
    CHECK(brick.default_map[1].colour[1] == 0.15);

    const pt::Kind& crackle = *pt::find_kind("crackle");
    CHECK(crackle.number == std::array<double, 2>{2.0, 0.0});
    CHECK(crackle.vector == glm::dvec3(-1.0, 1.0, 0.0));
    CHECK_FALSE(crackle.single_numbers);
    CHECK(crackle.default_map.size() == 2);  // black to white

    CHECK(pt::find_kind("quilted")->number == std::array<double, 2>{1.0, 1.0});
    CHECK(pt::find_kind("quilted")->normal != nullptr);
    CHECK(pt::find_kind("agate")->number[0] == 1.0);
    CHECK(pt::find_kind("agate")->default_map.size() == 6);
    CHECK(pt::find_kind("marble")->wave == pt::Wave::Triangle);
    CHECK(pt::find_kind("marble")->own_turbulence);
    CHECK(pt::find_kind("gradient")->argument == pt::Kind::Argument::Vector);
    CHECK(pt::find_kind("mandel")->argument == pt::Kind::Argument::Number);
    CHECK(pt::find_kind("hexagon")->colours == 3);
    CHECK(pt::find_kind("bozo")->default_map.size() == 6);
    CHECK(pt::find_kind("bozo")->normal == nullptr);
    CHECK(pt::find_kind("bumps")->normal != nullptr);
    CHECK(pt::find_kind("spotted")->single_numbers);
}

TEST_CASE("a kind's settings are set by name and refused on another kind",
          "[language][pattern][registry]") {
    const auto scene = read(R"(
sphere { 0, 1 pigment { brick mortar 0.1 + 0.2 * clock brick_size <1, 2, 3> } }
sphere { 0, 1 pigment { crackle metric 1 offset 0.25 form <1, 0, 0> } }
sphere { 0, 1 pigment { quilted control0 0.3 control1 0.7 } }
sphere { 0, 1 pigment { agate agate_turb 0.5 } }
)");
    const pt::Pattern& brick = pigment_pattern(scene, 0);
    CHECK(brick.number[pt::kinds::Brick::kMortar].depends_on_time());
    CHECK(brick.number[pt::kinds::Brick::kMortar](1.0) == Approx(0.3));
    CHECK(brick.vector.c[2].constant() == 3.0);
    const pt::Pattern& crackle = pigment_pattern(scene, 1);
    CHECK(crackle.number[pt::kinds::Crackle::kMetric].constant() == 1.0);
    CHECK(crackle.number[pt::kinds::Crackle::kOffset].constant() == 0.25);
    CHECK(crackle.vector.c[0].constant() == 1.0);
    const pt::Pattern& quilted = pigment_pattern(scene, 2);
    CHECK(quilted.number[pt::kinds::Quilted::kControl0].constant() == 0.3);
    CHECK(quilted.number[pt::kinds::Quilted::kControl1].constant() == 0.7);
    CHECK(pigment_pattern(scene, 3).number[pt::kinds::Agate::kAgateTurb].constant() == 0.5);

    const auto says = [](const std::string& text, const std::string& what) {
        const std::string message = hexant::test::error_of(text).what();
        INFO(message);
        return message.find(what) != std::string::npos;
    };
    CHECK(says("sphere { 0, 1 pigment { bozo mortar 0.2 } }",
               "mortar belongs to brick, not to bozo"));
    CHECK(says("sphere { 0, 1 pigment { rgb 1 metric 2 } }",
               "metric belongs to crackle, not to a plain colour"));
    CHECK(says("sphere { 0, 1 pigment { brick form <1, 0, 0> } }",
               "form belongs to crackle, not to brick"));
}

TEST_CASE("square paves the x-z plane with POV-Ray's four colours", "[pattern][registry]") {
    // The values are POV-Ray 3.7's, read from one-pixel renders of each
    // square's centre (tests/tracer/pov_reference/README.md, "Patterns").
    const pt::Kind& square = *pt::find_kind("square");
    const pt::Values v;
    const auto at = [&](double x, double y, double z) {
        return square.value(glm::dvec3(x, y, z), v);
    };
    CHECK(at(0.5, 0.0, 0.5) == 0.0);
    CHECK(at(0.5, 0.0, 1.5) == 1.0);
    CHECK(at(1.5, 0.0, 1.5) == 2.0);
    CHECK(at(1.5, 0.0, 0.5) == 3.0);
    CHECK(at(-0.5, 0.0, 0.5) == 3.0);   // floor(-0.5) = -1 is odd
    CHECK(at(-0.5, 7.0, -0.5) == 2.0);  // y is not read
    CHECK(at(2.0, 0.0, 0.0) == 0.0);    // an edge takes the square above it
    // Past int's range the parity still comes from the double, and a
    // non-finite point is square 0: no undefined cast.
    CHECK(at(3.0e9 + 1.5, 0.0, 0.5) == 3.0);
    CHECK(at(1.0e300, 0.0, 0.5) == 0.0);
    CHECK(at(std::numeric_limits<double>::infinity(), 0.0, 0.0) == 0.0);
    CHECK(at(std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0) == 0.0);
    CHECK(square.argument == pt::Kind::Argument::Colours);
    CHECK(square.colours == 4);
    CHECK_FALSE(square.frequency);
    REQUIRE(square.default_map.size() == 4);
    CHECK(square.default_map[3].colour == std::array<double, 5>{1, 1, 0, 0, 0});
    CHECK(hexant::test::error_of(
              "sphere { 0, 1 pigment { square rgb 1, rgb 0, rgb 1, rgb 0, rgb 1 } }")
              .what() ==
          std::string("test.pov:1:25: square takes at most 4 colours, not 5 values"));
}

TEST_CASE("triangular tiles the x-z plane with POV-Ray's six colours", "[pattern][registry]") {
    // POV-Ray 3.7's triangular_pattern: around the vertex at the origin the
    // six triangles are 0 (above, between x = 0 and 1), 1, ..., and the
    // fold repeats every 3 along x and sqrt(3) along z.
    const pt::Kind& triangular = *pt::find_kind("triangular");
    const pt::Values v;
    const auto at = [&](double x, double z) { return triangular.value(glm::dvec3(x, 0.0, z), v); };
    CHECK(at(0.5, 0.2) == 0.0);  // the triangle standing on [0, 1]
    CHECK(at(0.1, 0.7) == 1.0);  // left of it (above the edge from x = 0)
    CHECK(at(0.9, 0.7) == 3.0);  // right of it
    CHECK(at(1.5, 0.2) == 4.0);  // the next column's, numbered on by 2
    CHECK(at(0.5, 1.5) == 5.0);  // the upper half mirrors: 5 - 0
    CHECK(at(3.5, 0.2) == at(0.5, 0.2));
    CHECK(at(0.5, 0.2 + std::sqrt(3.0)) == at(0.5, 0.2));
    CHECK(at(std::numeric_limits<double>::quiet_NaN(), 0.0) == 0.0);
    CHECK(triangular.colours == 6);
    CHECK_FALSE(triangular.frequency);
    REQUIRE(triangular.default_map.size() == 6);
    CHECK(triangular.default_map[5].colour == std::array<double, 5>{1, 0, 1, 0, 0});
}
