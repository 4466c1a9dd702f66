// blob { } as the language reads it (runtime/objects/blob/blob.hpp, the
// grammar's blob_block): POV-Ray 3.7's component syntaxes, the threshold,
// time functions, and the refusals.
#include <algorithm>
#include <string>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "runtime/objects/shapes.hpp"
#include "tests/language/scene_text.hpp"

namespace rt = hexant::runtime;
using hexant::test::error_of;

namespace {

rt::Blob blob_of(const std::string& text) {
    const auto scene = hexant::language::parse_scene_text(text, "t.pov", {});
    REQUIRE(scene.objects.size() == 1);
    return std::get<rt::Blob>(scene.objects[0]->shape);
}

bool says(const std::string& scene, const std::string& part) {
    const std::string message = error_of(scene).what();
    INFO(message);
    return message.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE("blob reads its components in POV-Ray's three syntaxes", "[language][blob]") {
    using Kind = rt::geometry::BlobComponent::Kind;
    const auto b = blob_of(
        "blob { threshold 0.4 sphere { <1, 2, 3>, 1.5, 2 } sphere { 0, 1 strength -0.5 } "
        "cylinder { <0, 0, 0>, <0, 1, 0>, 0.3, strength 1 } component 3, 0.7, <4, 5, 6> "
        "#for (i, 0, 1) sphere { <i, 0, 0>, 1, 1 } #end sturm hierarchy off translate x }");
    REQUIRE(b.kinds.size() == 6);
    CHECK(b.threshold.constant() == 0.4);
    CHECK(b.kinds[0] == Kind::sphere);
    CHECK(b.a[0](0.0) == glm::dvec3(1, 2, 3));
    CHECK(b.radii[0].constant() == 1.5);
    CHECK(b.strengths[0].constant() == 2.0);
    CHECK(b.strengths[1].constant() == -0.5);
    CHECK(b.kinds[2] == Kind::cylinder);
    CHECK(b.b[2](0.0) == glm::dvec3(0, 1, 0));
    CHECK(b.radii[2].constant() == 0.3);
    // The old syntax: strength, radius, centre.
    CHECK(b.strengths[3].constant() == 3.0);
    CHECK(b.radii[3].constant() == 0.7);
    CHECK(b.a[3](0.0) == glm::dvec3(4, 5, 6));
    CHECK(b.a[5](0.0) == glm::dvec3(1, 0, 0));
    // The default threshold is POV-Ray's 1.
    CHECK(blob_of("blob { sphere { 0, 1, 1 } }").threshold.constant() == 1.0);
}

TEST_CASE("a blob's components and threshold may move with clock", "[language][blob]") {
    hexant::language::ParseOptions options;
    options.animation.initial_frame = 1;
    options.animation.final_frame = 2;
    const auto scene = hexant::language::parse_scene_text(
        "blob { threshold 0.5 + clock sphere { <clock, 0, 0>, 1, 1 - clock } }", "t.pov", options);
    const auto& b = std::get<rt::Blob>(scene.objects[0]->shape);
    CHECK(b.threshold.depends_on_time());
    CHECK(b.a[0].depends_on_time());
    CHECK(b.strengths[0].depends_on_time());
    CHECK_FALSE(b.radii[0].depends_on_time());
    const auto moving = scene.objects[0]->timed_parameters();
    CHECK(std::find(moving.begin(), moving.end(), "threshold") != moving.end());
    CHECK(std::find(moving.begin(), moving.end(), "a") != moving.end());
}

TEST_CASE("a blob's refusals name what is wrong", "[language][blob]") {
    CHECK(says("blob { sphere { 0, 1 } }", "a centre, a radius and a strength"));
    CHECK(says("blob { cylinder { 0, y, 1 } }", "two ends, a radius and a strength"));
    // A component takes POV-Ray's transforms only, not hexant's deformations.
    CHECK(says("blob { sphere { 0, 1, 1 twist y, 1 } }", "found 'twist'"));
    CHECK(says("sphere { 0, 1 threshold 2 }",
               "'threshold' belongs to a blob or isosurface, not a sphere"));
    CHECK(says("blob { sphere { \"a\", 1, 1 } }", "blob sphere's centre"));
}

TEST_CASE("a blob component reads its own transforms and texture", "[language][blob]") {
    hexant::language::ParseOptions options;
    options.animation.initial_frame = 1;
    options.animation.final_frame = 2;
    const auto scene = hexant::language::parse_scene_text(
        "blob { sphere { 0, 1, 1 pigment { rgb <1, 0, 0> } scale <2, 1, 1> translate x } "
        "cylinder { 0, y, 0.5, 1 rotate z * 90 * clock } sphere { 0, 1, 1 } "
        "pigment { rgb 1 } translate 3 * y }",
        "t.pov", options);
    const auto& b = std::get<rt::Blob>(scene.objects[0]->shape);
    REQUIRE(b.transforms.size() == 3);
    // Component space to blob space: scale, then translate (the blob's own
    // translate stays the blob's).
    const glm::dmat4 m = b.transforms[0].matrix_at(0.0);
    CHECK(glm::dvec3(m * glm::dvec4(1, 1, 1, 1)) == glm::dvec3(3, 1, 1));
    CHECK(b.transforms[1].depends_on_time());
    CHECK(b.transforms[2].empty());
    // The first has a texture of its own, moved with the transforms after
    // it; the others lend the blob's.
    REQUIRE(b.textures.size() == 1);
    CHECK(b.texture_index == std::vector<int>{0, -1, -1});
    CHECK_FALSE(b.textures[0].transform.empty());
    const auto moving = scene.objects[0]->timed_parameters();
    CHECK(std::find(moving.begin(), moving.end(), "transforms") != moving.end());
}
