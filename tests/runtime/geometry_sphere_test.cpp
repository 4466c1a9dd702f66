// Static ray/sphere geometry: analytic hits, rays aimed at sampled surface
// points at every scale (radii 1e-6 to 1e6, origins up to 1e6 away, centres
// far from the origin), grazing rays against a long double reference,
// inside() against the distance, and surface_may_meet around surface points.
#include "geometry_test_support.hpp"
#include "runtime/objects/sphere/sphere_geometry.hpp"

using namespace geometry_test;
using hexant::runtime::geometry::sphere_uv;
using hexant::runtime::geometry::SphereGeometry;

namespace {

SurfaceSample sample_sphere(const SphereGeometry& g, Random& random) {
    const glm::dvec3 n = random.unit_vector();
    return {g.center + g.radius * n, n, g.radius};
}

double sphere_residual(const SphereGeometry& g, const glm::dvec3& p) {
    const long double x = (long double)p.x - g.center.x, y = (long double)p.y - g.center.y,
                      z = (long double)p.z - g.center.z;
    return static_cast<double>(std::fabs(std::sqrt(x * x + y * y + z * z) - g.radius));
}

}  // namespace

TEST_CASE("sphere: analytic hits, normals, uv and ranges", "[runtime][geometry]") {
    const SphereGeometry g{{0.0, 0.0, 0.0}, 2.0};
    auto hit = intersect(g, Ray3{{0.0, 0.0, -10.0}, {0.0, 0.0, 1.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == 8.0);
    CHECK(hit->normal == glm::dvec3(0.0, 0.0, -1.0));
    CHECK(hit->point == glm::dvec3(0.0, 0.0, -2.0));
    CHECK(hit->part == 0);
    // uv from the normal (formed when a hit is shaded, not by intersect):
    // -z is three quarters of a turn from +x toward +z.
    CHECK(sphere_uv(hit->normal).x == Approx(0.75));
    CHECK(sphere_uv(hit->normal).y == Approx(0.5));
    // A direction of length 2 halves s.
    hit = intersect(g, Ray3{{0.0, 0.0, -10.0}, {0.0, 0.0, 2.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == 4.0);
    // From inside: the far side, normal outward.
    hit = intersect(g, Ray3{{0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == 2.0);
    CHECK(hit->normal == glm::dvec3(0.0, 0.0, 1.0));
    // s_min is strict; s_max excludes.
    hit = intersect(g, Ray3{{0.0, 0.0, -10.0}, {0.0, 0.0, 1.0}}, 8.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == 12.0);
    CHECK_FALSE(intersect(g, Ray3{{0.0, 0.0, -10.0}, {0.0, 0.0, 1.0}}, 0.0, 8.0));
    CHECK_FALSE(intersect(g, Ray3{{0.0, 0.0, -10.0}, {0.0, 0.0, -1.0}}, 0.0, kInf));
    // Poles: v = 0 at -y and 1 at +y.
    hit = intersect(g, Ray3{{0.0, 10.0, 0.0}, {0.0, -1.0, 0.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(sphere_uv(hit->normal).y == Approx(1.0));
    // +x is u = 0, +z a quarter turn.
    hit = intersect(g, Ray3{{0.0, 0.0, 10.0}, {0.0, 0.0, -1.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(sphere_uv(hit->normal).x == Approx(0.25));
    // Degenerate spheres and directions: no hit.
    CHECK_FALSE(intersect(SphereGeometry{{0, 0, 0}, 0.0}, Ray3{{0, 0, -5}, {0, 0, 1}}, 0.0, kInf));
    CHECK_FALSE(intersect(SphereGeometry{{0, 0, 0}, -1.0}, Ray3{{0, 0, -5}, {0, 0, 1}}, 0.0, kInf));
    CHECK_FALSE(intersect(g, Ray3{{0, 0, -5}, {0, 0, 0}}, 0.0, kInf));
    // Bounds.
    const Box3 b = object_bounds(SphereGeometry{{1.0, 2.0, 3.0}, 0.5});
    CHECK(b.lo == glm::dvec3(0.5, 1.5, 2.5));
    CHECK(b.hi == glm::dvec3(1.5, 2.5, 3.5));
}

TEST_CASE("sphere: rays aimed at surface points at every scale", "[runtime][geometry]") {
    Random random(11);
    struct Case {
        const char* name;
        SphereGeometry g;
        double distance;
    };
    const Case cases[] = {
        {"sphere r=1 near", {{0.0, 0.0, 0.0}, 1.0}, 5.0},
        {"sphere r=1 from 1e6", {{0.0, 0.0, 0.0}, 1.0}, 1e6},
        {"sphere r=1e-6 from 1e6", {{0.3, -0.2, 0.1}, 1e-6}, 1e6},
        {"sphere r=1e-6 from 1e-5", {{0.3, -0.2, 0.1}, 1e-6}, 1e-5},
        {"sphere r=1e6 from 1e6", {{-2e6, 1e6, 3e5}, 1e6}, 1e6},
        {"sphere r=1e6 from 3e6", {{0.0, 0.0, 0.0}, 1e6}, 3e6},
        {"sphere r=1 at 1e6 from 1e6", {{1e6, -1e6, 1e6}, 1.0}, 1e6},
    };
    for (const Case& c : cases) {
        INFO(c.name);
        const AimStats stats = aim_at_surface(
            c.g, [&](Random& r) { return sample_sphere(c.g, r); },
            [&](const glm::dvec3& p) { return sphere_residual(c.g, p); }, c.g.radius, c.distance,
            true, 2000, random);
        report(c.name, stats);
        CHECK(stats.grazing_misses <= stats.rays / 50);
        // On the sphere to a few ulps of the coordinates; s exact to a few
        // ulps for front hits; the point agrees with origin + s dir.
        CHECK(stats.max_residual < 16.0 * kEps);
        CHECK(stats.max_front_s_error < 64.0 * kEps);
        CHECK(stats.max_point_mismatch < 16.0 * kEps);
    }
}

TEST_CASE("sphere: grazing rays against a long double reference", "[runtime][geometry]") {
    Random random(12);
    for (const double r : {1e-6, 1.0, 1e6}) {
        const SphereGeometry g{{0.25 * r, -0.5 * r, 2.0 * r}, r};
        for (int i = 0; i < 2000; ++i) {
            // A ray at distance b from the centre, b within 1e-7 of r either way.
            const glm::dvec3 axis = random.unit_vector();
            glm::dvec3 side = glm::normalize(glm::cross(axis, random.unit_vector()));
            const double b = r * (1.0 + random.uniform(-1e-7, 1e-7));
            const double far = r * random.log_uniform(2.0, 1e6);
            const glm::dvec3 origin = g.center + b * side - far * axis;
            const auto hit = intersect(g, Ray3{origin, axis}, 0.0, kInf);
            // A long double reference from the ray as rounded, formed
            // geometrically: the distance of the line from the centre (a
            // cross product, no cancellation of squares) and the half chord.
            const long double fx = (long double)origin.x - g.center.x,
                              fy = (long double)origin.y - g.center.y,
                              fz = (long double)origin.z - g.center.z;
            const long double ux = axis.x, uy = axis.y, uz = axis.z;
            const long double uu = std::sqrt(ux * ux + uy * uy + uz * uz);
            const long double cx = fy * uz - fz * uy, cy = fz * ux - fx * uz,
                              cz = fx * uy - fy * ux;
            const long double line = std::sqrt(cx * cx + cy * cy + cz * cz) / uu;
            const long double gap = (long double)r - line;
            if (std::fabs((double)gap) < 1e-10 * r) continue;  // tangent within rounding
            INFO("r " << r << " b/r-1 " << b / r - 1.0);
            REQUIRE(hit.has_value() == (gap > 0));
            if (hit) {
                const long double along = (fx * ux + fy * uy + fz * uz) / uu;
                const long double half = std::sqrt(gap * ((long double)r + line));
                const long double s_ref = (-along - half) / uu;
                CHECK(sphere_residual(g, hit->point) < 16.0 * kEps * (r + length_ld(hit->point)));
                // The near root of a grazing ray is ill-conditioned in s by
                // r / half chord; in the residual it is not.
                const double cond = r * r / (double)half;
                CHECK(std::fabs(hit->s - (double)s_ref) <=
                      16.0 * kEps * (std::fabs((double)s_ref) + cond));
            }
        }
    }
}

TEST_CASE("sphere: inside, finite rays, may-meet", "[runtime][geometry]") {
    Random random(13);
    for (const double r : {1e-6, 1.0, 1e6}) {
        const SphereGeometry g{{3.0 * r, -1.0 * r, 1e6}, r};
        for (int i = 0; i < 5000; ++i) {
            const glm::dvec3 p = g.center + random.in_cube(2.0 * r);
            const double d = sphere_residual(g, p);
            if (d < 1e-9 * r) continue;
            const glm::dvec3 f = p - g.center;
            CHECK(inside(g, p) == (glm::dot(f, f) < r * r));
        }
        CHECK(random_rays_are_finite(g, r, g.center, 3000, random) > 100);
        boxes_around_surface(
            g, [&](Random& rr) { return sample_sphere(g, rr); }, r, 10000, random);
        // The test can say no: boxes wholly inside and wholly outside.
        CHECK_FALSE(surface_may_meet(g, Box3{g.center - 0.5 * r, g.center + 0.5 * r}));
        CHECK_FALSE(surface_may_meet(g, Box3{g.center + 0.75 * r, g.center + 2.0 * r}));
        CHECK(surface_may_meet(g, Box3{g.center - 2.0 * r, g.center + 2.0 * r}));
    }
}
