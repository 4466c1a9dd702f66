// An instance (runtime/objects/instance_object.hpp) answers every question
// as its members would, each placed in the world on its own: the same first
// hits along rays at random instants, the same normals, points and texture
// coordinates, the same inside, and bounds that hold every hit. And the
// factory builds one only where it may.
#include "runtime/objects/instance_object.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "object_test_support.hpp"
#include "runtime/texture/texture_evaluator.hpp"

namespace rt = hexant::runtime;
using object_test::Random;

namespace {

// Nineteen members of many kinds, with their own transforms and textures, a
// nested union, a difference and a clipped member, under one moving,
// turning and stretching transform.
std::string moving_union(const std::string& members_extra = "",
                         const std::string& motion =
                             "rotate y * 90 * clock scale <1, 1 + clock, "
                             "1> translate <2 * clock, 0, 0>") {
    std::string sdl = "union {\n";
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 3; ++j) {
            const double x = -1.5 + i, z = -1.0 + j;
            sdl += "  sphere { <" + std::to_string(x) + ", 0, " + std::to_string(z) +
                   ">, 0.35 pigment { checker rgb 1, rgb 0 scale 0.1 } }\n";
        }
    sdl += R"(
  box { <-2, -1, -2>, <2, -0.8, 2> rotate x * 10 }
  triangle { <-2, 1, 0>, <0, 1.5, 1>, <2, 1, 0> }
  union { cylinder { <0, 0, 0>, <0, 1, 0>, 0.2 translate <1, 0.5, 1> }
          torus { 0.5, 0.1 translate <-1, 0.8, -1> } }
  difference { box { -0.4, 0.4 } sphere { 0, 0.5 } translate <0, 1.2, -1.5> }
  sphere { <0, -0.3, 1.8>, 0.6 clipped_by { box { <-1, -0.2, 1>, <1, 1, 3> } } }
  cone { <1.5, 0.5, -1.5>, 0.3, <1.5, 1.2, -1.5>, 0 }
)" + members_extra +
           "  pigment { rgb <0.9, 0.5, 0.2> }\n  " + motion + "\n}\n";
    return sdl;
}

struct Built {
    object_test::Parsed parsed;
    std::vector<rt::IntelligentObjectPtr> instanced, split;
};

Built build(const std::string& sdl) {
    Built b{object_test::parse(sdl), {}, {}};
    for (const auto& record : b.parsed.scene.objects) {
        rt::make_intelligent_objects(*record, b.parsed.scene.default_texture, b.instanced,
                                     rt::ObjectOptions{true});
        rt::make_intelligent_objects(*record, b.parsed.scene.default_texture, b.split,
                                     rt::ObjectOptions{false});
    }
    return b;
}

std::optional<rt::ObjectHit> nearest(const std::vector<rt::IntelligentObjectPtr>& objects,
                                     const rt::Ray4& ray, double s_max) {
    std::optional<rt::ObjectHit> best;
    for (const auto& o : objects)
        if (auto hit = o->intersect(ray, 0.0, best ? best->s : s_max)) best = hit;
    return best;
}

}  // namespace

TEST_CASE("an instance meets rays, shades and holds points as its members placed one by one",
          "[runtime][instance]") {
    const Built b = build(moving_union());
    REQUIRE(b.instanced.size() == 1);
    const auto* instance = dynamic_cast<const rt::InstanceObject*>(b.instanced.front().get());
    REQUIRE(instance != nullptr);
    CHECK(instance->size() == 19);  // the nested union split into its two
    REQUIRE(b.split.size() == 19);
    CHECK(instance->moves());

    Random random(43);
    int hits = 0, disagreements = 0;
    constexpr int kRays = 20000;
    for (int i = 0; i < kRays; ++i) {
        const double t = random.uniform(0.0, 1.0);
        const glm::dvec3 from = 8.0 * random.unit_vector();
        const glm::dvec3 target(random.uniform(-2.5, 4.5), random.uniform(-2, 3),
                                random.uniform(-2.5, 2.5));
        const rt::Ray4 ray{rt::Event(from, t), rt::Event(target - from, 0.0)};
        const auto a = instance->intersect(ray, 0.0, 1e30);
        const auto e = nearest(b.split, ray, 1e30);
        CHECK(instance->occluded(ray, 0.0, 1e30) == a.has_value());
        if (a.has_value() != e.has_value()) {
            ++disagreements;  // a ray through an edge, by rounding
            continue;
        }
        if (!a) continue;
        ++hits;
        // The same first hit, to the rounding of one more map.
        if (std::fabs(a->s - e->s) > 1e-9 * (1.0 + e->s)) {
            ++disagreements;
            continue;
        }
        const rt::SurfacePoint pa = instance->complete(ray, *a);
        const rt::SurfacePoint pe = e->object->complete(ray, *e);
        CHECK(glm::distance(glm::dvec3(pa.event), glm::dvec3(pe.event)) < 1e-9);
        CHECK(pa.event.w == pe.event.w);
        CHECK(glm::dot(pa.geometric_normal, pe.geometric_normal) > 1.0 - 1e-9);
        CHECK(glm::dot(pa.shading_normal, pe.shading_normal) > 1.0 - 1e-9);
        CHECK(glm::distance(pa.uv, pe.uv) < 1e-9);
        // Its error bound covers as much: within a few times the member's.
        CHECK(glm::length(pa.error) <= 4.0 * glm::length(pe.error) + 1e-12);
        // The same texture, in world terms: the same colour there.
        REQUIRE(pa.texture != nullptr);
        REQUIRE(pe.texture != nullptr);
        CHECK(pa.texture->at(glm::dvec3(pa.event), pa.uv, t).colour ==
              pe.texture->at(glm::dvec3(pe.event), pe.uv, t).colour);
        // Every hit lies in the instance's bounds at its instant and over
        // any stretch of time around it.
        CHECK(instance->placed_box_at(t).contains(a->event));
        const double dt = random.uniform(0.0, 0.3);
        const rt::Interval around(std::max(0.0, t - dt), std::min(1.0, t + dt));
        CHECK(instance->box_over(around).contains(a->event));
        rt::Box4 region;
        region.lo = rt::Event(glm::dvec3(a->event) - glm::dvec3(0.5), around.lo);
        region.hi = rt::Event(glm::dvec3(a->event) + glm::dvec3(0.5), around.hi);
        std::vector<rt::SlabBound> bounds;
        instance->bound(region, bounds);
        CHECK(std::any_of(bounds.begin(), bounds.end(),
                          [&](const rt::SlabBound& s) { return s.contains(a->event); }));
    }
    CHECK(hits > kRays / 4);
    // (Rays through an edge may go either way by the last bit.)
    CHECK(disagreements <= kRays / 1000);

    // Inside: the union's inside, at random events.
    int inside = 0;
    for (int i = 0; i < 20000; ++i) {
        const rt::Event e(random.uniform(-3, 5), random.uniform(-2, 3), random.uniform(-3, 3),
                          random.uniform(0, 1));
        const bool any = std::any_of(b.split.begin(), b.split.end(),
                                     [&](const auto& o) { return o->inside(e); });
        CHECK(instance->inside(e) == any);
        inside += any;
    }
    CHECK(inside > 100);
}

TEST_CASE("the factory builds an instance only where its members stand still and carry no flags",
          "[runtime][instance]") {
    const auto count = [](const std::string& sdl) { return build(sdl).instanced.size(); };
    CHECK(count(moving_union()) == 1);
    // A member that moves in the union, or lives part of the time.
    CHECK(count(moving_union("sphere { 0, 1 translate y * clock }")) > 1);
    CHECK(count(moving_union("#if (clock < 0.5) sphere { 0, 1 } #end")) > 1);
    // A member with a flag or an interior of its own.
    CHECK(count(moving_union("sphere { 0, 1 no_shadow }")) > 1);
    CHECK(count(moving_union("sphere { 0, 1 no_image }")) > 1);
    CHECK(count(moving_union("sphere { 0, 1 interior { ior 1.5 } }")) > 1);
    // Nothing moves, or the motion deforms.
    CHECK(count(moving_union("", "translate x")) > 1);
    CHECK(count(moving_union("", "twist y, 10 * clock")) > 1);
    // A member made in the world: a bicubic_patch (subdivided there), a
    // bounded_by (its box axis-aligned there).
    CHECK(count(moving_union(
              "bicubic_patch { type 1 flatness 0.1 u_steps 2 v_steps 2 "
              "<0,0,0>,<1,1,0>,<2,-1,0>,<3,0,0>, <0,1,1>,<1,2,1>,<2,0,1>,<3,1,1>, "
              "<0,-1,2>,<1,0,2>,<2,-2,2>,<3,-1,2>, <0,0,3>,<1,1,3>,<2,-1,3>,<3,0,3> }")) > 1);
    CHECK(count(moving_union("sphere { 0, 1 bounded_by { box { -0.5, 0.5 } } }")) > 1);
    // A plane among the members: no bound to sweep.
    CHECK(count(moving_union("plane { y, -5 }")) > 1);
    // A texture that changes with time is fine (it is in world terms).
    CHECK(count(moving_union("sphere { 0, 0.1 pigment { rgb clock } }")) == 1);
    // Too few members to pay.
    CHECK(count("union { sphere { 0, 1 } sphere { x, 1 } translate x * clock }") == 2);
}
