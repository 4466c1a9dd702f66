// uv_mapping (runtime/texture/material.hpp, UvMapping; runtime/objects/primitive.hpp,
// has_uv_mapping): what a surface's (u, v) is for each kind, that a
// uv-mapped pigment reads it and nothing else (not the object's transforms,
// not a transform written around a declared copy), and where the language
// refuses it. The look against POV-Ray 3.7 is the pov_reference test's
// (textures/uv_mapping.pov).
#include <cmath>
#include <numbers>
#include <string>

#include <catch2/catch.hpp>

#include "../language/scene_text.hpp"
#include "object_test_support.hpp"
#include "runtime/texture/texture_evaluator.hpp"

using namespace object_test;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Seen {
    rt::SurfacePoint point;
    rt::MaterialSample material;
};

// What a ray from `origin` along `direction` at time t sees on the first
// object of `sdl`: the completed surface point and its top material.
Seen look(const std::string& sdl, const glm::dvec3& origin, const glm::dvec3& direction,
          double t = 0.0) {
    const Parsed parsed = parse(sdl);
    const rt::IntelligentObject& object = *parsed.objects.front();
    const rt::Ray4 ray{rt::Event(origin, t), rt::Event(direction, 0.0)};
    const auto hit = object.intersect(ray, 0.0, kInf);
    REQUIRE(hit);
    Seen seen{object.complete(ray, *hit), {}};
    seen.material =
        seen.point.texture->at(glm::dvec3(seen.point.event), seen.point.uv, seen.point.event.w);
    return seen;
}

// A uv-mapped gradient x through a ramp from black to white: its red is u
// (in [0, 1), POV-Ray's ramp wave), in single precision as POV-Ray's maps.
const char* kRamp = "pigment { uv_mapping gradient x color_map { [0 rgb 0] [1 rgb 1] } }";

}  // namespace

TEST_CASE("uv_mapping reads a sphere's (u, v), which its own turn carries and no other",
          "[object][pattern]") {
    // A ray along +z meets the sphere's front at height 0.5: POV-Ray's
    // sphere uv there is u = 0.75 (atan2(z, x) / 2 pi, from 0), v = 0.5 +
    // asin(0.5) / pi.
    const std::string sphere = std::string("sphere { 0, 1 ") + kRamp;
    const Seen plain = look(sphere + " }", {0, 0.5, -5}, {0, 0, 1});
    CHECK(plain.point.uv.x == Approx(0.75).epsilon(1e-12));
    CHECK(plain.point.uv.y == Approx(0.5 + std::asin(0.5) / std::numbers::pi).epsilon(1e-12));
    CHECK(plain.material.colour.x == Approx(plain.point.uv.x).margin(1e-6));
    // Turned 45 degrees about y and moved: the ray meets another object
    // point, an eighth of a turn along u, and the colour is that point's
    // (the map turns with the object, no world transform reaches it) ...
    const Seen turned =
        look(sphere + " rotate y * 45 translate <3, 0, 0> }", {3, 0.5, -5}, {0, 0, 1});
    CHECK(std::fabs(turned.point.uv.x - 0.75) == Approx(0.125).epsilon(1e-9));
    CHECK(turned.material.colour.x == Approx(turned.point.uv.x).margin(1e-6));
    // ... and a scale written in the pigment acts in uv space: 0.5 wide
    // ramps, so the colour is 2u mod 1.
    const Seen scaled = look(
        "sphere { 0, 1 pigment { uv_mapping gradient x color_map { [0 rgb 0] [1 rgb 1] } scale 0.5 "
        "} "
        "scale 3 }",
        {0, 1.5, -9}, {0, 0, 1});
    const double u = scaled.point.uv.x;
    CHECK(scaled.material.colour.x == Approx(std::fmod(2.0 * u, 1.0)).margin(1e-6));
}

TEST_CASE("a kind POV-Ray gives no (u, v) of its own maps the world point's x and y",
          "[object][pattern]") {
    // POV-Ray's ObjectBase::UVCoord: the intersection's world x and y.
    for (const std::string shape :
         {"cylinder { <0, -1, 0>, <0, 1, 0>, 0.5 ", "cone { <0, -1, 0>, 0.6, <0, 1, 0>, 0.2 ",
          "superellipsoid { <0.5, 0.5> scale 0.5 "}) {
        INFO(shape);
        const Seen seen = look(shape + kRamp + " translate <0.25, 0, 0> rotate z * 10 }",
                               {0.3, 0.2, -5}, {0, 0, 1});
        CHECK(seen.point.uv.x == seen.point.event.x);
        CHECK(seen.point.uv.y == seen.point.event.y);
        const double expected = seen.point.event.x - std::floor(seen.point.event.x);
        CHECK(seen.material.colour.x == Approx(expected).margin(1e-6));
    }
}

TEST_CASE("a mesh's (u, v) blends its uv_vectors, and is (0, 0) without them",
          "[object][pattern]") {
    const char* with =
        "mesh2 { vertex_vectors { 3, <0, 0, 0>, <1, 0, 0>, <0, 1, 0> } "
        "uv_vectors { 3, <0.1, 0.2>, <0.9, 0.2>, <0.1, 0.6> } face_indices { 1, <0, 1, 2> } ";
    const Seen seen = look(std::string(with) + kRamp + " }", {0.25, 0.5, -5}, {0, 0, 1});
    // Barycentric weights (0.25, 0.25, 0.5) of the three corners.
    CHECK(seen.point.uv.x == Approx(0.25 * 0.1 + 0.25 * 0.9 + 0.5 * 0.1).epsilon(1e-12));
    CHECK(seen.point.uv.y == Approx(0.25 * 0.2 + 0.25 * 0.2 + 0.5 * 0.6).epsilon(1e-12));
    // A mesh's triangle with uv_vectors (POV-Ray's Parse_Three_UVCoords):
    // the same blend.
    const Seen listed =
        look(std::string("mesh { triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> uv_vectors <0.1, 0.2>, "
                         "<0.9, 0.2>, <0.1, 0.6> } ") +
                 kRamp + " }",
             {0.25, 0.5, -5}, {0, 0, 1});
    CHECK(listed.point.uv.x == Approx(seen.point.uv.x).epsilon(1e-12));
    CHECK(listed.point.uv.y == Approx(seen.point.uv.y).epsilon(1e-12));
    CHECK(listed.material.colour.x == Approx(listed.point.uv.x).margin(1e-6));
    const Seen none =
        look(std::string("mesh { triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> } ") + kRamp + " }",
             {0.25, 0.5, -5}, {0, 0, 1});
    CHECK(none.point.uv == glm::dvec2(0.0));
}

TEST_CASE("a uv-mapped pigment, normal or texture takes transforms only from its own block",
          "[language][pattern]") {
    const Parsed parsed = parse(R"(
#declare P = pigment { uv_mapping checker rgb 0, rgb 1 scale 0.25 }
#declare T = texture { uv_mapping pigment { checker rgb 0, rgb 1 } normal { bumps 0.5 } scale 0.5 }
sphere { 0, 1 pigment { P scale 4 } }
sphere { 0, 1 texture { T scale 3 } rotate y * 30 }
sphere { 0, 1 normal { uv_mapping bumps 0.5 scale 0.1 } normal { scale 9 } }
)");
    const auto& objects = parsed.scene.objects;
    // The declared pigment's own scale only (one step), not the outer 4.
    const rt::Pigment& p = objects[0]->texture->pigment;
    CHECK(p.uv_mapping == rt::UvMapping::Closed);
    CHECK(p.transform.steps().size() == 1);
    // The texture keeps its own scale; the copy's scale and the object's
    // turn wait in uv_outside (for its normal's linear part alone).
    const rt::Texture& t = *objects[1]->texture;
    CHECK(t.uv_mapping == rt::UvMapping::Closed);
    CHECK(t.transform.steps().size() == 1);
    CHECK(t.uv_outside.steps().size() == 2);
    // A second normal { } on the object modifies the uv-mapped one: no
    // transform reaches it.
    const rt::Normal& n = *objects[2]->texture->normal;
    CHECK(n.uv_mapping == rt::UvMapping::Closed);
    CHECK(n.transform.steps().size() == 1);
}

TEST_CASE("a second pigment or normal over a uv-mapped one replaces it, as in POV-Ray",
          "[language][pattern]") {
    const Parsed parsed = parse(R"(
sphere { 0, 1 pigment { uv_mapping checker rgb 0, rgb 1 scale 0.1 } pigment { checker rgb 0, rgb 1 scale 0.2 } }
sphere { 0, 1 pigment { checker rgb 0, rgb 1 scale 0.1 } pigment { uv_mapping checker rgb 0, rgb 1 scale 0.2 } }
sphere { 0, 1 normal { uv_mapping bumps 0.5 scale 0.1 } normal { dents 0.5 scale 0.2 } }
)");
    const auto& objects = parsed.scene.objects;
    // The plain pattern alone, with its own scale (POV-Ray's Parse_Pattern
    // puts a new pattern in place of the uv map and what was inside it).
    const rt::Pigment& plain = objects[0]->texture->pigment;
    CHECK(plain.uv_mapping == rt::UvMapping::Off);
    CHECK(plain.transform.steps().size() == 1);
    // The uv map from the default pigment: the earlier scale does not reach it.
    const rt::Pigment& mapped = objects[1]->texture->pigment;
    CHECK(mapped.uv_mapping == rt::UvMapping::Closed);
    CHECK(mapped.transform.steps().size() == 1);
    const rt::Normal& n = *objects[2]->texture->normal;
    CHECK(n.uv_mapping == rt::UvMapping::Off);
    CHECK(n.patterned->kind->name == "dents");
    CHECK(n.transform.steps().size() == 1);
}

TEST_CASE("uv_mapping where there is no surface is an error naming it", "[language][pattern]") {
    using hexant::test::error_of;
    CHECK_THAT(
        error_of("camera { location -z look_at 0 normal { uv_mapping bumps 0.5 } }").formatted(),
        Catch::Contains("uv_mapping") && Catch::Contains("camera"));
    CHECK_THAT(error_of("sky_sphere { pigment { uv_mapping gradient y } }").formatted(),
               Catch::Contains("uv_mapping") && Catch::Contains("sky_sphere"));
    // uv_vectors belong to a mesh's triangle (POV-Ray 3.7 reads them only there).
    const rt::SceneDescription alone = hexant::language::parse_scene_text(
        "triangle { 0, x, y uv_vectors <0, 0>, <1, 0>, <0, 1> }\n", "test.pov", {});
    REQUIRE(alone.objects.size() == 1);
    CHECK_THROWS_WITH(rt::make_intelligent_object(*alone.objects.front()),
                      Catch::Contains("uv_vectors belong to a triangle in a mesh"));
    CHECK_THAT(error_of("mesh { triangle { 0, x, y uv_vectors <0, 0>, <1, 0> } }").formatted(),
               Catch::Contains("three"));
    // (Not a finish's word: the usual error at the place.)
    CHECK_THAT(error_of("sphere { 0, 1 finish { uv_mapping } }").formatted(),
               Catch::Contains("test.pov:1:"));
}
