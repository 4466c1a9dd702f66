// The other messages of intelligent objects, and how the factory builds
// them from records: complete() (normals through non-uniform scales and
// deformations, the material at the hit's time, a checker that moves with
// its object), occupancy() (exact for a static solid inside the region,
// sampled otherwise), CSG (union, intersection, difference, inverse) and
// what a group passes down to its children.
#include <cmath>
#include <string>

#include <catch2/catch.hpp>

#include "object_test_support.hpp"
#include "runtime/geometry/curved_path_root.hpp"
#include "runtime/geometry/offset_ray.hpp"
#include "runtime/objects/object_error.hpp"
#include "runtime/texture/texture_evaluator.hpp"
#include "runtime/work_counts.hpp"

using namespace object_test;

namespace {

// The material the object's texture gives at a hit it returned (the top
// layer of what is picked there).
rt::MaterialSample material(const rt::IntelligentObject& object, const rt::Ray4& ray,
                            const rt::ObjectHit& hit) {
    const rt::SurfacePoint p = object.complete(ray, hit);
    return p.texture->at(glm::dvec3(p.event), p.uv, p.event.w);
}

constexpr double kInf = std::numeric_limits<double>::infinity();

rt::Ray4 ray(const glm::dvec3& origin, const glm::dvec3& direction, double t = 0.0) {
    return {rt::Event(origin, t), rt::Event(direction, 0.0)};
}

rt::Box4 box4(const glm::dvec3& lo, const glm::dvec3& hi, double t0 = 0.0, double t1 = 1.0) {
    rt::Box4 b;
    b.lo = rt::Event(lo, t0);
    b.hi = rt::Event(hi, t1);
    return b;
}

}  // namespace

TEST_CASE("complete: the normal of a scaled sphere is the ellipsoid's gradient", "[object]") {
    // Turning with the clock, and turned still (a still object keeps its
    // normals' map from the start: Primitive's Still).
    const bool turning = GENERATE(true, false);
    const Parsed parsed =
        parse(turning ? "sphere { <0, 0, 0>, 1 scale <1, 2, 3> rotate <0, 0, 90 * clock> }\n"
                      : "sphere { <0, 0, 0>, 1 scale <1, 2, 3> rotate <0, 0, 36> }\n");
    const auto& object = *parsed.objects.front();
    REQUIRE(object.moves() == turning);
    Random random(3);
    for (int i = 0; i < 500; ++i) {
        const double t = turning ? random.uniform(0.0, 1.0) : 0.4;
        const glm::dvec3 d = random.unit_vector();
        const rt::Ray4 r = ray(-10.0 * d + 0.3 * random.unit_vector(), d, t);
        const auto hit = object.intersect(r, 0.0, kInf);
        if (!hit) continue;
        const rt::SurfacePoint p = object.complete(r, *hit);
        // Undo the rotation, take the gradient of x^2 + y^2/4 + z^2/9, rotate back.
        const double angle = -90.0 * t * kDegree;
        const glm::dvec3 w(hit->event);
        const glm::dvec3 q(w.x * std::cos(angle) - w.y * std::sin(angle),
                           w.x * std::sin(angle) + w.y * std::cos(angle), w.z);
        const glm::dvec3 g(q.x, q.y / 4.0, q.z / 9.0);
        const glm::dvec3 n(g.x * std::cos(-angle) - g.y * std::sin(-angle),
                           g.x * std::sin(-angle) + g.y * std::cos(-angle), g.z);
        REQUIRE(glm::length(p.geometric_normal - glm::normalize(n)) < 1e-9);
        REQUIRE(glm::dot(p.geometric_normal, d) < 0.0);  // outward, facing the ray
    }
}

TEST_CASE("complete: a twisted box's normals match finite differences of the surface",
          "[object][deformed]") {
    const Parsed parsed = parse("box { <-0.5, -1, -0.5>, <0.5, 1, 0.5> twist <0, 1, 0>, 90 }\n");
    const auto& object = *parsed.objects.front();
    const rt::ObjectRecord& record = *parsed.scene.objects.front();
    Random random(5);
    int checked = 0;
    for (int i = 0; i < 300; ++i) {
        const glm::dvec3 d = random.unit_vector();
        const rt::Ray4 r = ray(-5.0 * d + 0.4 * random.unit_vector(), d);
        const auto hit = object.intersect(r, 0.0, kInf);
        if (!hit || hit->part % 3 == 1) continue;  // the y faces are not turned: skip them
        const rt::SurfacePoint p = object.complete(r, *hit);
        // Two tangents of the face through the object point, mapped by the
        // reference: the normal is perpendicular to both.
        const glm::dvec3 o = hit->object_point;
        const glm::dvec3 n = hit->object_normal;
        glm::dvec3 u, v;
        perpendicular_pair(n, u, v);
        const double h = 1e-6;
        const auto world = [&](const glm::dvec3& q) {
            return reference_to_world(record.transform, q, 0.0);
        };
        const glm::dvec3 tu = (world(o + h * u) - world(o - h * u)) / (2 * h);
        const glm::dvec3 tv = (world(o + h * v) - world(o - h * v)) / (2 * h);
        REQUIRE(std::fabs(glm::dot(p.geometric_normal, glm::normalize(tu))) < 1e-6);
        REQUIRE(std::fabs(glm::dot(p.geometric_normal, glm::normalize(tv))) < 1e-6);
        REQUIRE(glm::dot(p.geometric_normal, d) < 0.0);
        ++checked;
    }
    CHECK(checked > 50);
}

TEST_CASE("complete: colours and finishes are evaluated at the hit's time", "[object]") {
    const Parsed parsed = parse(
        "sphere { <0, 0, 0>, 1 pigment { color rgb <clock, 0, 1 - clock> } "
        "finish { phong 0.5 * clock ambient 0.2 } }\n");
    const auto& object = *parsed.objects.front();
    for (const double t : {0.0, 0.25, 0.9}) {
        const rt::Ray4 r = ray({0, 0, -5}, {0, 0, 1}, t);
        const auto hit = object.intersect(r, 0.0, kInf);
        REQUIRE(hit);
        const rt::MaterialSample m = material(object, r, *hit);
        CHECK(m.colour.x == Approx(t));
        CHECK(m.colour.z == Approx(1.0 - t));
        CHECK(m.phong == Approx(0.5 * t));
        CHECK(m.ambient.x == Approx(0.2));
    }
}

TEST_CASE("complete: a checker moves with its object", "[object]") {
    // The checker is written before the translation, so it travels with
    // the box: the square under a fixed point of the box stays the same.
    const Parsed parsed = parse(
        "box { <-2, -2, 0>, <2, 2, 1> pigment { checker color rgb 1, color rgb 0 } "
        "translate <3 * clock, 0, 0> }\n");
    const auto& object = *parsed.objects.front();
    for (const double t : {0.0, 0.3, 0.7}) {
        const glm::dvec3 origin(0.5 + 3.0 * t, 0.5, -5.0);  // object point (0.5, 0.5)
        const rt::Ray4 r = ray(origin, {0, 0, 1}, t);
        const auto hit = object.intersect(r, 0.0, kInf);
        REQUIRE(hit);
        CHECK(material(object, r, *hit).colour.x == 1.0);
        const rt::Ray4 r2 = ray(origin + glm::dvec3(1.0, 0.0, 0.0), {0, 0, 1}, t);
        const auto hit2 = object.intersect(r2, 0.0, kInf);
        REQUIRE(hit2);
        CHECK(material(object, r2, *hit2).colour.x == 0.0);
    }
}

TEST_CASE("occupancy: exact for a static solid in the region, sampled otherwise", "[object]") {
    const Parsed parsed = parse(
        "sphere { <0, 0, 0>, 1 scale 0.5 }\n"
        "box { <0, 0, 0>, <1, 1, 1> }\n"
        "sphere { <0, 0, 0>, 0.5 translate <2 * clock, 0, 0> }\n"
        "triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }\n");
    const double pi = kPi;
    // The sphere of radius 0.5 inside a cube of side 2: exactly its share.
    const rt::Box4 cube = box4({-1, -1, -1}, {1, 1, 1});
    CHECK(parsed.objects[0]->occupancy(cube) ==
          Approx(4.0 / 3.0 * pi * 0.125 / 8.0).epsilon(1e-12));
    // Half of the unit box inside [0.5, 1.5]^3 x [0, 1]: an eighth of it,
    // by 256 stratified samples (4 standard errors of a fraction: 0.125).
    const rt::Box4 corner = box4({0.5, 0.5, 0.5}, {1.5, 1.5, 1.5});
    CHECK(parsed.objects[1]->occupancy(corner) == Approx(0.125).margin(0.125));
    // Samples of a box whose faces fall on the strata: well inside it is 1.
    CHECK(parsed.objects[1]->occupancy(box4({0.2, 0.2, 0.2}, {0.8, 0.8, 0.8})) == 1.0);
    // The moving sphere fills the region around its path for a while only.
    const double moving = parsed.objects[2]->occupancy(box4({-1, -1, -1}, {3, 1, 1}));
    CHECK(moving > 0.0);
    CHECK(moving < 0.2);
    CHECK(parsed.objects[2]->occupancy(box4({10, 10, 10}, {11, 11, 11})) == 0.0);
    // Flat shapes fill nothing.
    CHECK(parsed.objects[3]->occupancy(cube) == 0.0);
}

TEST_CASE("CSG: union, intersection, difference and inverse combine their children", "[object]") {
    const Parsed parsed = parse(
        "union { sphere { <-1, 0, 0>, 0.6 } sphere { <1, 0, 0>, 0.6 } translate <0, 0, 2> }\n"
        "intersection { sphere { <-0.5, 0, 0>, 1 } sphere { <0.5, 0, 0>, 1 } }\n"
        "difference { box { <-1, -1, -1>, <1, 1, 1> } sphere { <0, 0, -1>, 0.5 } }\n"
        "sphere { <0, 0, 0>, 1 inverse }\n");
    REQUIRE(parsed.objects.size() == 4);
    const rt::Ray4 along_z = ray({0, 0, -5}, {0, 0, 1});

    // Union: the group's translation reached both children.
    const auto u = parsed.objects[0]->intersect(ray({1, 0, -5}, {0, 0, 1}), 0.0, kInf);
    REQUIRE(u);
    CHECK(u->s == Approx(5.0 + 2.0 - 0.6));
    CHECK_FALSE(parsed.objects[0]->intersect(along_z, 0.0, kInf));
    std::vector<rt::SlabBound> bounds;
    parsed.objects[0]->bound(box4({-10, -10, -10}, {10, 10, 10}), bounds);
    CHECK(bounds.size() == 2);  // one tight bound per child

    // Intersection of two spheres: the lens between x = -0.5 and 0.5.
    const auto lens = parsed.objects[1]->intersect(along_z, 0.0, kInf);
    REQUIRE(lens);
    CHECK(lens->s == Approx(5.0 - std::sqrt(0.75)));
    CHECK(parsed.objects[1]->inside(rt::Event(0, 0, 0, 0)));
    CHECK_FALSE(parsed.objects[1]->inside(rt::Event(0.9, 0, 0, 0)));

    // Difference: the ray enters the box's bite, a spherical cut whose
    // normal points out of the remaining solid, back towards the bite.
    const auto cut = parsed.objects[2]->intersect(along_z, 0.0, kInf);
    REQUIRE(cut);
    CHECK(cut->s == Approx(5.0 - 1.0 + 0.5));
    const rt::SurfacePoint p = parsed.objects[2]->complete(along_z, *cut);
    CHECK(p.geometric_normal.z == Approx(-1.0));
    CHECK_FALSE(parsed.objects[2]->inside(rt::Event(0, 0, -0.9, 0)));
    CHECK(parsed.objects[2]->inside(rt::Event(0.9, 0.9, -0.9, 0)));
    const auto side = parsed.objects[2]->intersect(ray({0.8, 0, -5}, {0, 0, 1}), 0.0, kInf);
    REQUIRE(side);
    CHECK(side->s == Approx(4.0));

    // Inverse: inside and outside swap, the surface stays.
    CHECK_FALSE(parsed.objects[3]->inside(rt::Event(0, 0, 0, 0)));
    CHECK(parsed.objects[3]->inside(rt::Event(3, 0, 0, 0)));
    const auto inv = parsed.objects[3]->intersect(along_z, 0.0, kInf);
    REQUIRE(inv);
    CHECK(parsed.objects[3]->complete(along_z, *inv).geometric_normal.z == Approx(1.0));
}

TEST_CASE("factory: textures, no_shadow and the default texture pass down groups", "[object]") {
    const Parsed parsed = parse(
        "#default { pigment { color rgb <0, 1, 0> } }\n"
        "union { sphere { <0, 0, 0>, 1 } sphere { <3, 0, 0>, 1 pigment { color rgb <0, 0, 1> } } "
        "pigment { color rgb <1, 0, 0> } no_shadow }\n"
        "sphere { <0, 0, 10>, 1 }\n");
    REQUIRE(parsed.objects.size() == 2);
    const auto colour_at = [&](const rt::IntelligentObject& o, const glm::dvec3& from) {
        const rt::Ray4 r = ray(from, {0, -1, 0});
        const auto hit = o.intersect(r, 0.0, kInf);
        REQUIRE(hit);
        return material(o, r, *hit).colour;
    };
    CHECK(colour_at(*parsed.objects[0], {0, 5, 0}) == glm::dvec3(1, 0, 0));
    CHECK(colour_at(*parsed.objects[0], {3, 5, 0}) == glm::dvec3(0, 0, 1));
    CHECK(colour_at(*parsed.objects[1], {0, 5, 10}) == glm::dvec3(0, 1, 0));
    CHECK_FALSE(parsed.objects[0]->casts_shadow());
    CHECK(parsed.objects[1]->casts_shadow());
}

TEST_CASE("factory: a deformed plane is an error naming its place", "[object]") {
    hexant::language::ParseOptions options;
    const auto scene = hexant::language::parse_scene_text(
        "sphere { 0, 1 }\n  plane { y, 0 twist y, 10 }\n", "bent.pov", options);
    REQUIRE(scene.objects.size() == 2);
    CHECK_NOTHROW(rt::make_intelligent_object(*scene.objects[0]));
    try {
        rt::make_intelligent_object(*scene.objects[1]);
        FAIL("no error");
    } catch (const rt::ObjectError& e) {
        const std::string what = e.what();
        INFO(what);
        CHECK(what.find("bent.pov:2") != std::string::npos);
        CHECK(what.find("plane") != std::string::npos);
    }
}

TEST_CASE("factory: a pattern hexant does not have is an error naming where it was written",
          "[object]") {
    // The interpreter already stops at such an object; the factory checks
    // again for records built by other means.
    rt::ObjectRecord record;
    record.shape = rt::Sphere{rt::Vector3Function{{0.0, 0.0, 0.0}}, 1.0};
    rt::Texture texture;
    texture.pigment.pattern = rt::Pigment::Pattern::Unsupported;
    texture.pigment.unsupported_name = "bozo";
    texture.pigment.unsupported_place.file = "patterns.pov";
    texture.pigment.unsupported_place.line = 4;
    record.texture = texture;
    try {
        rt::make_intelligent_object(record);
        FAIL("no error");
    } catch (const rt::ObjectError& e) {
        const std::string what = e.what();
        INFO(what);
        CHECK(what.find("patterns.pov:4") != std::string::npos);
        CHECK(what.find("bozo") != std::string::npos);
    }
}

TEST_CASE("only deformed objects and time-travelling rays enter the curved-path solver",
          "[object]") {
    const Parsed plain = parse(
        "sphere { <0, 0, 0>, 1 rotate <0, 360 * clock, 0> translate <clock, 0, 0> }\n"
        "box { <-1, -1, -1>, <1, 1, 1> scale <1, 1 + clock, 1> }\n"
        "torus { 1, 0.3 }\n");
    const Parsed bent = parse("box { <-0.2, -1, -0.2>, <0.2, 1, 0.2> bend y, 30 }\n");
    Random random(8);
    const std::uint64_t before = rt::curved_path_solves();
    for (int i = 0; i < 200; ++i) {
        const glm::dvec3 d = random.unit_vector();
        const rt::Ray4 r = ray(-5.0 * d + 0.5 * random.unit_vector(), d, random.uniform(0.0, 1.0));
        for (const auto& object : plain.objects) object->intersect(r, 0.0, kInf);
    }
    CHECK(rt::curved_path_solves() == before);
    // A deformed object solves on the curve; so does a ray whose time runs
    // through a moving object.
    bent.objects.front()->intersect(ray({0, 0, -5}, {0, 0, 1}), 0.0, kInf);
    CHECK(rt::curved_path_solves() == before + 1);
    const rt::Ray4 travelling{rt::Event(0, 0, -5, 0), rt::Event(0, 0, 1, 0.1)};
    plain.objects.front()->intersect(travelling, 0.0, 10.0);
    CHECK(rt::curved_path_solves() == before + 2);
}

TEST_CASE("a deformation that is none at the ray's instant costs a straight-ray test", "[object]") {
    // The twist starts from nothing at clock 0: a ray at that instant meets
    // a plain box, found by the straight-ray routine (a ray lying in a face
    // plane once cost the curved search tens of thousands of pieces there).
    const Parsed twisting =
        parse("box { <-0.3, 0, -0.3>, <0.3, 2, 0.3> twist y, 360 * 12 * clock }\n");
    const Parsed plain = parse("box { <-0.3, 0, -0.3>, <0.3, 2, 0.3> }\n");
    const auto& object = *twisting.objects.front();
    Random random(3);
    const std::uint64_t before = rt::curved_path_solves();
    for (int i = 0; i < 200; ++i) {
        const glm::dvec3 d = random.unit_vector();
        const rt::Ray4 r = ray(glm::dvec3(0, 1, 0) - 5.0 * d + 0.3 * random.unit_vector(), d, 0.0);
        const auto got = object.intersect(r, 0.0, kInf);
        const auto expected = plain.objects.front()->intersect(r, 0.0, kInf);
        REQUIRE(bool(got) == bool(expected));
        if (got) CHECK(got->s == expected->s);
    }
    CHECK(rt::curved_path_solves() == before);
    CHECK(object.intersect(ray({0, 1, -5}, {0.05, 0, 1}, 0.5), 0.0, kInf));  // twisted by now
    CHECK(rt::curved_path_solves() == before + 1);
}

TEST_CASE("a ray in the plane of a bent object's end is not refined ulp by ulp", "[object]") {
    // Beyond the centre of curvature the inverse bend's angle jumps from pi
    // to -pi across that plane; a ray lying in it once straddled the jump on
    // the sign of a zero, every piece spanning both branches, and the search
    // ran into its limit of pieces. Counted in deformation maps.
    const Parsed bent = parse("cylinder { 0, 2 * y, 0.3 bend y, 98 translate -x * 1.5 }\n");
    const auto& object = *bent.objects.front();
    Random random(5);
    for (int i = 0; i < 20; ++i) {
        const double angle = random.uniform(-0.6, 0.6);
        const glm::dvec3 d(std::cos(angle), 0.0, std::sin(angle));
        const glm::dvec3 aim(-1.5 + random.uniform(-0.2, 0.2), 0.0, 0.6 + random.uniform(0.0, 0.4));
        const std::uint64_t before = rt::this_thread_work.deformation_maps;
        (void)object.intersect(ray(aim - 5.0 * d, d), 0.0, kInf);
        CHECK(rt::this_thread_work.deformation_maps - before < 20000);
    }
}

TEST_CASE("secondary rays offset from a hit do not find the surface they leave", "[object]") {
    // Reflected rays leave a convex solid and must not meet it again at any
    // distance; a far placement and a fast motion make the hit point's
    // rounding large in absolute terms, which the offset must clear.
    const Parsed parsed = parse(
        "sphere { <0, 0, 0>, 1 translate <1e6, -3e5, 2e5> }\n"
        "sphere { <0, 0, 0>, 1e-4 translate <2, 0, 0> rotate <0, 36000 * clock, 0> }\n"
        "box { <-1, -2, -3>, <1, 2, 3> rotate <10, 20, 30> translate <5e5, 0, 0> }\n");
    const glm::dvec3 centres[] = {{1e6, -3e5, 2e5}, {2, 0, 0}, {5e5, 0, 0}};
    Random random(12);
    for (std::size_t k = 0; k < parsed.objects.size(); ++k) {
        const auto& object = *parsed.objects[k];
        int reflected = 0;
        for (int i = 0; i < 2000; ++i) {
            const double t = k == 1 ? random.uniform(0.0, 1.0) : 0.0;
            const double angle = 36000.0 * t * kDegree;
            const glm::dvec3 c =
                k == 1 ? glm::dvec3(2.0 * std::cos(angle), 0.0, -2.0 * std::sin(angle))
                       : centres[k];
            const glm::dvec3 d = random.unit_vector();
            const double size = k == 1 ? 1e-4 : 1.0;
            const rt::Ray4 r = ray(c - 10.0 * size * d + 0.9 * size * random.unit_vector(), d, t);
            const auto hit = object.intersect(r, 0.0, kInf);
            if (!hit) continue;
            const rt::SurfacePoint p = object.complete(r, *hit);
            const glm::dvec3 n = p.geometric_normal;
            const glm::dvec3 out = d - 2.0 * glm::dot(d, n) * n;
            const glm::dvec3 start = rt::geometry::offset_ray(glm::dvec3(hit->event), n);
            const auto again = object.intersect(ray(start, out, t), 0.0, kInf);
            INFO("object " << k << " ray " << i);
            REQUIRE_FALSE(again);
            ++reflected;
        }
        CHECK(reflected > 500);
    }
}
