// blob's static geometry (runtime/objects/blob/blob_geometry.hpp): the
// field as POV-Ray's components compute it, hits against sampling the field
// along the ray, normals against the field's gradient, inside, bounds.
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <vector>

#include <catch2/catch.hpp>

#include "runtime/objects/blob/blob_geometry.hpp"

namespace {

using hexant::runtime::geometry::BlobComponent;
using hexant::runtime::geometry::BlobGeometry;
using hexant::runtime::geometry::Box3;
using hexant::runtime::geometry::Ray3;
namespace geo = hexant::runtime::geometry;

constexpr double kInf = std::numeric_limits<double>::infinity();

BlobComponent sphere(glm::dvec3 c, double r, double s) {
    return {BlobComponent::Kind::sphere, c, glm::dvec3(0.0), r, s};
}
BlobComponent cylinder(glm::dvec3 a, glm::dvec3 b, double r, double s) {
    return {BlobComponent::Kind::cylinder, a, b, r, s};
}

// POV-Ray's calculate_element_field for a cylinder and its two hemispheres,
// in the cylinder's frame (z along the axis from the base).
double pov_cylinder_field(const BlobComponent& c, const glm::dvec3& p) {
    const double len = glm::length(c.b - c.a);
    const glm::dvec3 z = (c.b - c.a) / len;
    const glm::dvec3 v = p - c.a;
    const double pz = glm::dot(v, z);
    const glm::dvec3 radial = v - pz * z;
    const double rad2 = c.radius * c.radius;
    const double c0 = c.strength / (rad2 * rad2), c1 = -2.0 * c.strength / rad2, c2 = c.strength;
    double density = 0.0;
    const auto add = [&](double d2) { density += d2 * (d2 * c0 + c1) + c2; };
    if (pz >= 0.0 && pz <= len && glm::dot(radial, radial) <= rad2) add(glm::dot(radial, radial));
    if (pz <= 0.0 && glm::dot(v, v) <= rad2) add(glm::dot(v, v));
    const glm::dvec3 w = p - c.b;
    if (pz - len >= 0.0 && glm::dot(w, w) <= rad2) add(glm::dot(w, w));
    return density;
}

BlobGeometry random_blob(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    BlobGeometry b;
    b.threshold = 0.3 + 0.5 * (u(rng) + 1.0);
    const int n = 2 + static_cast<int>((u(rng) + 1.0) * 3);
    for (int i = 0; i < n; ++i) {
        const glm::dvec3 c(u(rng), u(rng), u(rng));
        const double r = 0.5 + 0.6 * (u(rng) + 1.0);
        const double s = i % 4 == 3 ? -1.0 * (u(rng) + 1.0) : 1.0 + (u(rng) + 1.0);
        if (i % 2)
            b.components.push_back(cylinder(c, c + glm::dvec3(u(rng), u(rng), u(rng)), r, s));
        else
            b.components.push_back(sphere(c, r, s));
        // Every third carries its own transform: a stretch, a shear and a
        // shift (POV-Ray's Element->Trans).
        if (i % 3 == 2) {
            glm::dmat4 m(1.0);
            for (int col = 0; col < 3; ++col)
                for (int row = 0; row < 3; ++row)
                    m[col][row] = (col == row ? 1.0 + 0.6 * u(rng) : 0.4 * u(rng));
            m[3] = glm::dvec4(0.5 * u(rng), 0.5 * u(rng), 0.5 * u(rng), 1.0);
            b.components.back().transformed = true;
            b.components.back().to_blob = m;
            b.components.back().to_component = glm::inverse(m);
        }
    }
    return b;
}

glm::dvec3 random_unit(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (;;) {
        const glm::dvec3 v(u(rng), u(rng), u(rng));
        const double l = glm::length(v);
        if (l > 0.1 && l <= 1.0) return v / l;
    }
}

// The first sign change of field - threshold along the ray in (0, t_end),
// sampled at n points and refined by bisection.
std::optional<double> sampled_crossing(const BlobGeometry& b, const Ray3& ray, double t_end,
                                       int n) {
    const auto f = [&](double t) {
        return geo::blob_field(b, ray.origin + t * ray.direction) - b.threshold;
    };
    double t0 = 0.0, f0 = f(0.0);
    for (int i = 1; i <= n; ++i) {
        const double t1 = t_end * i / n, f1 = f(t1);
        if ((f0 < 0.0) != (f1 < 0.0)) {
            double lo = t0, hi = t1;
            for (int k = 0; k < 80; ++k) {
                const double m = 0.5 * (lo + hi);
                if ((f(m) < 0.0) == (f0 < 0.0))
                    lo = m;
                else
                    hi = m;
            }
            return 0.5 * (lo + hi);
        }
        t0 = t1;
        f0 = f1;
    }
    return std::nullopt;
}

}  // namespace

TEST_CASE("blob: the field is POV-Ray's", "[geometry][blob]") {
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    const BlobComponent s = sphere({0.2, -0.1, 0.3}, 1.3, 2.5);
    const BlobComponent c = cylinder({-0.5, 0.1, 0.2}, {0.7, 0.4, -0.3}, 0.8, -1.7);
    for (int i = 0; i < 2000; ++i) {
        const glm::dvec3 p(u(rng), u(rng), u(rng));
        // Sphere: c0 d^4 + c1 d^2 + c2 with POV-Ray's Make_Blob coefficients.
        const double d2 = glm::dot(p - s.a, p - s.a), r2 = s.radius * s.radius;
        const double want =
            d2 < r2 ? d2 * (d2 * s.strength / (r2 * r2) - 2.0 * s.strength / r2) + s.strength : 0.0;
        REQUIRE(geo::blob_field({1.0, {s}}, p) == Approx(want).margin(1e-12));
        REQUIRE(geo::blob_field({1.0, {c}}, p) == Approx(pov_cylinder_field(c, p)).margin(1e-12));
        REQUIRE(geo::blob_field({1.0, {s, c}}, p) ==
                Approx(want + pov_cylinder_field(c, p)).margin(1e-12));
    }
}

TEST_CASE("blob: one sphere is a sphere", "[geometry][blob]") {
    // s (1 - r^2 / R^2)^2 = t at r = R sqrt(1 - sqrt(t / s)).
    const BlobGeometry b{0.5, {sphere({1.0, 2.0, 3.0}, 2.0, 2.0)}};
    const double r = 2.0 * std::sqrt(1.0 - std::sqrt(0.25));
    const auto h = geo::intersect(b, Ray3{{1.0, 2.0, -7.0}, {0.0, 0.0, 2.0}}, 0.0, kInf);
    REQUIRE(h);
    REQUIRE(h->s == Approx((10.0 - r) / 2.0).epsilon(1e-14));
    REQUIRE(glm::length(h->normal - glm::dvec3(0, 0, -1)) < 1e-12);
    REQUIRE(h->shading_normal == h->normal);
    // From inside: the far side; s_min/s_max respected.
    const auto out = geo::intersect(b, Ray3{{1.0, 2.0, 3.0}, {0.0, 0.0, 1.0}}, 0.0, kInf);
    REQUIRE(out);
    REQUIRE(out->s == Approx(r).epsilon(1e-14));
    REQUIRE(out->normal.z == Approx(1.0));
    REQUIRE_FALSE(geo::intersect(b, Ray3{{1.0, 2.0, 3.0}, {0.0, 0.0, 1.0}}, 0.0, 0.9 * r));
    REQUIRE(geo::inside(b, {1.0, 2.0, 3.0}));
    REQUIRE_FALSE(geo::inside(b, {1.0, 2.0, 3.0 + 1.01 * r}));
    const Box3 box = geo::object_bounds(b);
    REQUIRE(box.lo.x == -1.0);
    REQUIRE(box.hi.z == 5.0);
    // Threshold above the strength: nothing.
    REQUIRE_FALSE(geo::intersect(BlobGeometry{3.0, {sphere({0, 0, 0}, 1.0, 2.0)}},
                                 Ray3{{0, 0, -5}, {0, 0, 1}}, 0.0, kInf));
}

TEST_CASE("blob: a scaled, turned, moved sphere is its ellipsoid", "[geometry][blob]") {
    // One sphere of radius R, strength s, threshold T: a ball of radius
    // r0 = R sqrt(1 - sqrt(T / s)); scaled by <a, b, c>, turned 90 degrees
    // about z (x to y) and moved by m, the ellipsoid with semi-axes a r0
    // along y, b r0 along -x, c r0 along z, about m.
    const double radius = 1.5, s = 2.0, threshold = 0.5, a = 2.0, b = 0.5, c = 0.8;
    const double r0 = radius * std::sqrt(1.0 - std::sqrt(threshold / s));
    const glm::dvec3 m(0.3, -0.2, 1.0);
    BlobComponent e = sphere({0, 0, 0}, radius, s);
    e.transformed = true;
    // scale, then rotate z 90 (x -> y, y -> -x), then translate.
    e.to_blob = glm::dmat4(glm::dvec4(0, a, 0, 0), glm::dvec4(-b, 0, 0, 0), glm::dvec4(0, 0, c, 0),
                           glm::dvec4(m, 1.0));
    e.to_component = glm::inverse(e.to_blob);
    const BlobGeometry g{threshold, {e}};
    // Along y from below: the tip at m - a r0 y, normal -y.
    auto h = geo::intersect(g, Ray3{m - glm::dvec3(0, 10, 0), glm::dvec3(0, 1, 0)}, 0.0, kInf);
    REQUIRE(h);
    CHECK(h->point.y == Approx(m.y - a * r0).epsilon(1e-12));
    CHECK(glm::length(h->normal - glm::dvec3(0, -1, 0)) < 1e-9);
    // Along x from the right: at m + b r0 x.
    h = geo::intersect(g, Ray3{m + glm::dvec3(10, 0, 0), glm::dvec3(-2, 0, 0)}, 0.0, kInf);
    REQUIRE(h);
    CHECK(h->point.x == Approx(m.x + b * r0).epsilon(1e-12));
    CHECK(glm::length(h->normal - glm::dvec3(1, 0, 0)) < 1e-9);
    // A slanted ray meets it where the ellipsoid's equation says.
    const glm::dvec3 o = m + glm::dvec3(3, 2, -4), d = glm::normalize(m - o);
    h = geo::intersect(g, Ray3{o, d}, 0.0, kInf);
    REQUIRE(h);
    const glm::dvec3 q = h->point - m;
    CHECK(q.y * q.y / (a * a * r0 * r0) + q.x * q.x / (b * b * r0 * r0) +
              q.z * q.z / (c * c * r0 * r0) ==
          Approx(1.0).epsilon(1e-10));
    // Its bounds: the ellipsoid's reach's box, R (not r0) out.
    const Box3 box = geo::object_bounds(g);
    CHECK(box.lo.y <= m.y - a * radius);
    CHECK(box.hi.x >= m.x + b * radius);
    CHECK(box.hi.y == Approx(m.y + a * radius).epsilon(1e-12));
    // The components' densities: |field| each.
    std::vector<double> densities;
    geo::blob_component_densities(g, m, densities);
    REQUIRE(densities.size() == 1);
    CHECK(densities[0] == Approx(s));
}

TEST_CASE("blob: a cylinder is a capsule", "[geometry][blob]") {
    const BlobGeometry b{0.5, {cylinder({0, 0, 0}, {0, 3, 0}, 1.0, 2.0)}};
    const double r = std::sqrt(1.0 - std::sqrt(0.25));
    auto h = geo::intersect(b, Ray3{{-5, 1.5, 0}, {1, 0, 0}}, 0.0, kInf);
    REQUIRE(h);
    REQUIRE(h->s == Approx(5.0 - r).epsilon(1e-14));
    REQUIRE(glm::length(h->normal - glm::dvec3(-1, 0, 0)) < 1e-12);
    h = geo::intersect(b, Ray3{{0, 9, 0}, {0, -1, 0}}, 0.0, kInf);  // the apex cap
    REQUIRE(h);
    REQUIRE(h->s == Approx(6.0 - r).epsilon(1e-14));
    h = geo::intersect(b, Ray3{{0.3 * r, -4, 0}, {0, 1, 0}}, 0.0, kInf);  // the base cap, off axis
    REQUIRE(h);
    REQUIRE(glm::length(h->point - glm::dvec3(0.3 * r, -std::sqrt(r * r - 0.09 * r * r), 0)) <
            1e-12);
}

TEST_CASE("blob: hits against sampling the field along the ray", "[geometry][blob]") {
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int hits = 0, rays = 0;
    for (int k = 0; k < 60; ++k) {
        const BlobGeometry b = random_blob(rng);
        const Box3 box = geo::object_bounds(b);
        for (int i = 0; i < 100; ++i) {
            const glm::dvec3 target =
                box.lo + glm::dvec3(u(rng), u(rng), u(rng)) * (box.hi - box.lo);
            const glm::dvec3 origin = target + 6.0 * random_unit(rng);
            const Ray3 ray{origin, (target - origin) * (0.25 + u(rng))};
            const double t_end = 14.0 / glm::length(ray.direction);
            const auto want = sampled_crossing(b, ray, t_end, 4000);
            const auto got = geo::intersect(b, ray, 0.0, kInf);
            ++rays;
            INFO("blob " << k << " ray " << i);
            if (want) {
                // A sign change: a hit at or before it (a tangent touch the
                // samples stepped over may come first).
                REQUIRE(got);
                REQUIRE(got->s <= *want * (1.0 + 1e-9) + 1e-12);
                if (got->s < *want * (1.0 - 1e-6)) {
                    // Then it is a touch: the field reaches the threshold
                    // without crossing.
                    const double f = geo::blob_field(b, got->point) - b.threshold;
                    REQUIRE(std::fabs(f) < 1e-7);
                } else {
                    REQUIRE(got->s == Approx(*want).epsilon(1e-8));
                }
            }
            if (got) {
                ++hits;
                REQUIRE(geo::is_finite(*got));
                REQUIRE(std::fabs(glm::length(got->normal) - 1.0) < 1e-12);
                REQUIRE(std::fabs(geo::blob_field(b, got->point) - b.threshold) < 1e-7);
                REQUIRE(geo::surface_may_meet(b, Box3{got->point, got->point}));
                REQUIRE(got->point.x >= box.lo.x);
                REQUIRE(got->point.x <= box.hi.x);
                // The normal is -grad(field), by central differences.
                const double e = 1e-6;
                glm::dvec3 grad;
                for (int a = 0; a < 3; ++a) {
                    glm::dvec3 dp(0.0);
                    dp[a] = e;
                    grad[a] = (geo::blob_field(b, got->point + dp) -
                               geo::blob_field(b, got->point - dp)) /
                              (2 * e);
                }
                if (glm::length(grad) > 1e-3)
                    REQUIRE(glm::length(got->normal + glm::normalize(grad)) < 1e-5);
                // Inside where the field exceeds the threshold.
                const glm::dvec3 step = 1e-6 * got->normal;
                REQUIRE(geo::inside(b, got->point - step) ==
                        (geo::blob_field(b, got->point - step) > b.threshold - 1e-6));
            } else {
                REQUIRE_FALSE(want);
            }
        }
    }
    REQUIRE(hits > rays / 4);
}

TEST_CASE("blob: surface_may_meet and random rays", "[geometry][blob]") {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int k = 0; k < 20; ++k) {
        const BlobGeometry b = random_blob(rng);
        const Box3 box = geo::object_bounds(b);
        REQUIRE_FALSE(geo::surface_may_meet(b, Box3{box.hi + 0.1, box.hi + 1.0}));
        for (int i = 0; i < 300; ++i) {
            const double reach = std::pow(10.0, -2.0 + 8.0 * u(rng));
            const glm::dvec3 origin = 0.5 * (box.lo + box.hi) + reach * random_unit(rng);
            glm::dvec3 dir = i % 2 ? 0.5 * (box.lo + box.hi) - origin : random_unit(rng);
            if (i % 3 == 0) dir[i % 3] = 0.0;
            if (i % 13 == 0) dir = glm::dvec3(0.0);
            dir *= std::pow(10.0, -50.0 + 100.0 * u(rng));
            const auto h = geo::intersect(b, Ray3{origin, dir}, i % 4 ? 0.0 : -kInf, kInf);
            if (!h) continue;
            REQUIRE(geo::is_finite(*h));
            REQUIRE(dir != glm::dvec3(0.0));
            const double e = std::pow(10.0, -12.0 + 11.0 * u(rng));
            REQUIRE(geo::surface_may_meet(b, Box3{h->point - e * u(rng), h->point + e * u(rng)}));
        }
        // Boxes wholly inside the field's high part or outside everything.
        REQUIRE_FALSE(geo::surface_may_meet(b, Box3{box.lo - 3.0, box.lo - 2.0}));
    }
    const BlobGeometry one{0.5, {sphere({0, 0, 0}, 2.0, 2.0)}};
    REQUIRE_FALSE(
        geo::surface_may_meet(one, Box3{glm::dvec3(-0.1), glm::dvec3(0.1)}));  // all inside
    REQUIRE(geo::surface_may_meet(one, Box3{glm::dvec3(-2.0), glm::dvec3(2.0)}));
}
