// Static ray/superellipsoid geometry: first hits of random rays against an
// independent reference (the implicit function, written here from its
// textbook form in long double, sampled densely along the ray for sign
// changes and refined by bisection), the sphere case against the analytic
// sphere, normals against the reference function's finite-difference
// gradient, inside() against the function, bounds and surface_may_meet
// around sampled surface points, the volume against Monte Carlo, rays from
// 1e6 away aimed at surface points, and no NaN for extreme rays and
// exponents.
#include <vector>

#include "geometry_test_support.hpp"
#include "runtime/geometry/box_queries.hpp"
#include "runtime/objects/superellipsoid/superellipsoid_geometry.hpp"

using namespace geometry_test;
using hexant::runtime::geometry::make_superellipsoid;
using hexant::runtime::geometry::SuperellipsoidGeometry;
namespace geo = hexant::runtime::geometry;

namespace {

struct Exponents {
    double e, n;
};

// Round, boxy, pinched, starry, a cube, near-cube and extreme ones.
const std::vector<Exponents> kShapes = {{1.0, 1.0}, {0.25, 0.25}, {0.05, 0.6}, {2.0, 2.0},
                                        {3.0, 0.5}, {4.0, 4.0},   {0.0, 0.0},  {1e-3, 1e-3},
                                        {0.5, 2.5}, {1.0, 0.02},  {8.0, 1.0},  {2.0, 1e-4}};

// (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) - 1, in long double; e or n of
// 0 as the limit (max).
long double reference(const Exponents& s, long double x, long double y, long double z) {
    x = std::fabs(x);
    y = std::fabs(y);
    z = std::fabs(z);
    long double xy;
    if (s.e == 0.0) {
        xy = std::max(x, y);
    } else {
        // Scaled by the larger, as a norm.
        const long double m = std::max(x, y);
        if (m == 0.0L) {
            xy = 0.0L;
        } else {
            const long double p = 2.0L / s.e;
            xy = m * std::pow(std::pow(x / m, p) + std::pow(y / m, p), 1.0L / p);
        }
    }
    long double g;
    if (s.n == 0.0) {
        g = std::max(xy, z);
    } else {
        const long double m = std::max(xy, z);
        if (m == 0.0L) return -1.0L;
        const long double q = 2.0L / s.n;
        g = m * std::pow(std::pow(xy / m, q) + std::pow(z / m, q), 1.0L / q);
    }
    return g - 1.0L;
}

long double reference(const Exponents& s, const glm::dvec3& p) {
    return reference(s, p.x, p.y, p.z);
}

// The first sign change of the reference along the ray within (s_min, s_max),
// from `samples` samples over the ray's stretch in the box [-1.01, 1.01]^3,
// refined by bisection in long double. Negative when none.
double reference_hit(const Exponents& s, const Ray3& ray, double s_min, double s_max, int samples) {
    long double lo = s_min, hi = s_max;
    for (int i = 0; i < 3; ++i) {
        const long double o = ray.origin[i], d = ray.direction[i];
        if (d == 0.0L) {
            if (std::fabs(o) > 1.01L) return -1.0;
            continue;
        }
        long double a = (-1.01L - o) / d, b = (1.01L - o) / d;
        if (a > b) std::swap(a, b);
        lo = std::max(lo, a);
        hi = std::min(hi, b);
    }
    if (!(lo < hi)) return -1.0;
    auto f = [&](long double t) {
        return reference(s, ray.origin.x + t * (long double)ray.direction.x,
                         ray.origin.y + t * (long double)ray.direction.y,
                         ray.origin.z + t * (long double)ray.direction.z);
    };
    long double t0 = lo, f0 = f(lo);
    for (int i = 1; i <= samples; ++i) {
        const long double t1 = lo + (hi - lo) * i / samples;
        const long double f1 = f(t1);
        if ((f0 > 0.0L) != (f1 > 0.0L)) {
            long double a = t0, b = t1, fa = f0;
            for (int k = 0; k < 100; ++k) {
                const long double m = 0.5L * (a + b);
                const long double fm = f(m);
                if ((fm > 0.0L) == (fa > 0.0L)) {
                    a = m;
                    fa = fm;
                } else {
                    b = m;
                }
            }
            return static_cast<double>(0.5L * (a + b));
        }
        t0 = t1;
        f0 = f1;
    }
    return -1.0;
}

// A surface point in direction d: d / (F(d) + 1) (F + 1 is homogeneous).
glm::dvec3 surface_point(const Exponents& s, const glm::dvec3& d) {
    return d / static_cast<double>(reference(s, d) + 1.0L);
}

// The reference gradient by central differences in long double.
glm::dvec3 reference_gradient(const Exponents& s, const glm::dvec3& p, double h) {
    glm::dvec3 g;
    for (int i = 0; i < 3; ++i) {
        glm::dvec3 a = p, b = p;
        a[i] += h;
        b[i] -= h;
        g[i] = static_cast<double>((reference(s, b.x, b.y, b.z) - reference(s, a.x, a.y, a.z)) /
                                   (-2.0L * h));
    }
    return g;
}

}  // namespace

TEST_CASE("superellipsoid: POV-Ray's powers and limits", "[geometry][superellipsoid]") {
    const auto g = make_superellipsoid(0.5, 4.0);
    CHECK(g.valid);
    CHECK(g.px == 4.0);
    CHECK(g.pz == 0.5);
    const auto cube = make_superellipsoid(0.0, 0.0);
    CHECK(cube.valid);
    CHECK(std::isinf(cube.px));
    CHECK(geo::superellipsoid_function(cube, {0.5, -0.9, 0.2}) == Approx(-0.1));
    CHECK_FALSE(make_superellipsoid(-1.0, 1.0).valid);
    CHECK_FALSE(make_superellipsoid(1.0, std::nan("")).valid);
    CHECK_FALSE(make_superellipsoid(kInf, 1.0).valid);
    const auto bad = make_superellipsoid(-0.5, 1.0);
    CHECK_FALSE(geo::intersect(bad, {{0, 0, -5}, {0, 0, 1}}, 0.0, kInf));
    CHECK_FALSE(geo::inside(bad, glm::dvec3(0.0)));
    CHECK_FALSE(geo::surface_may_meet(bad, {glm::dvec3(-2), glm::dvec3(2)}));
    // The sphere: F = |p| - 1.
    const auto sphere = make_superellipsoid(1.0, 1.0);
    CHECK(geo::superellipsoid_function(sphere, {0.6, 0.0, 0.8}) == Approx(0.0).margin(1e-15));
    CHECK(geo::superellipsoid_function(sphere, {0.0, 0.0, 0.0}) == -1.0);
}

TEST_CASE("superellipsoid: the sphere case against the analytic sphere",
          "[geometry][superellipsoid]") {
    const auto g = make_superellipsoid(1.0, 1.0);
    Random random(11);
    for (int i = 0; i < 2000; ++i) {
        const glm::dvec3 origin = random.in_cube(3.0);
        const glm::dvec3 dir = random.unit_vector() * random.log_uniform(0.1, 10.0);
        const auto hit = geo::intersect(g, {origin, dir}, 0.0, kInf);
        // |o + s d|^2 = 1.
        const long double a = glm::dot(dir, dir), b = glm::dot(origin, dir),
                          c = (long double)glm::dot(origin, origin) - 1.0L;
        const long double disc = b * b - a * c;
        double expected = -1.0;
        if (disc >= 0.0L) {
            const long double r = std::sqrt(disc);
            const long double s0 = (-b - r) / a, s1 = (-b + r) / a;
            expected = s0 > 0.0L ? (double)s0 : s1 > 0.0L ? (double)s1 : -1.0;
        }
        if (expected < 0.0 || disc < 1e-6L * a) {
            if (expected < 0.0 && disc < -1e-6L * a) CHECK_FALSE(hit);
            continue;
        }
        REQUIRE(hit);
        CHECK(well_formed(*hit));
        CHECK(hit->s == Approx(expected).epsilon(1e-11).margin(1e-12));
        const glm::dvec3 p = origin + hit->s * dir;
        CHECK(glm::length(hit->normal - glm::normalize(p)) < 1e-9);
    }
}

TEST_CASE("superellipsoid: first hits against the sampled reference",
          "[geometry][superellipsoid]") {
    Random random(5);
    int compared = 0, extra = 0;
    for (const auto& s : kShapes) {
        const auto g = make_superellipsoid(s.e, s.n);
        for (int i = 0; i < 200; ++i) {
            // Rays through the box from outside, and from inside.
            const glm::dvec3 origin = i % 3 == 0 ? random.in_cube(0.9) : random.unit_vector() * 3.0;
            const glm::dvec3 target = random.in_cube(1.0);
            const glm::dvec3 dir = (target - origin) * random.log_uniform(0.2, 5.0);
            const auto hit = geo::intersect(g, {origin, dir}, 0.0, kInf);
            const double expected = reference_hit(s, {origin, dir}, 0.0, 1e30, 4000);
            if (hit) {
                CHECK(well_formed(*hit));
                // On the surface (the reference's residual over its gradient).
                const double res = (double)std::fabs(reference(s, hit->point));
                const glm::dvec3 grad = reference_gradient(s, hit->point, 1e-7);
                const double gl = glm::length(grad);
                if (gl > 1e-3 && std::isfinite(gl)) CHECK(res / gl < 1e-9);
                CHECK(glm::length(origin + hit->s * dir - hit->point) <
                      1e-12 * (1.0 + glm::length(origin)));
            }
            if (expected > 0.0) {
                ++compared;
                REQUIRE(hit);
                // Never beyond the reference's first crossing; before it only
                // by a crossing the samples stepped over.
                const double scale = glm::length(dir);
                CHECK(hit->s <= expected + 1e-9 / scale);
                if (hit->s < expected - 1e-9 / scale) {
                    ++extra;
                    // A thin sliver: the reference finds it with finer samples
                    // from just before the hit.
                    const double near = reference_hit(s, {origin, dir}, hit->s - 1e-6 / scale,
                                                      hit->s + 1e-6 / scale, 20000);
                    CHECK(near > 0.0);
                }
            } else if (hit) {
                ++extra;
                const double near =
                    reference_hit(s, {origin, dir}, hit->s - 1e-6 / glm::length(dir),
                                  hit->s + 1e-6 / glm::length(dir), 20000);
                CHECK(near > 0.0);
            }
        }
    }
    INFO("compared " << compared << ", hits between samples " << extra);
    CHECK(compared > 1300);
}

TEST_CASE("superellipsoid: thin grazing hits are found", "[geometry][superellipsoid]") {
    // A ray skimming a sphere 1e-7 inside its tangent plane crosses a chord
    // of length 2 sqrt(2e-7) ~ 9e-4; one near a cube's edge much less.
    const auto sphere = make_superellipsoid(1.0, 1.0);
    const auto hit = geo::intersect(sphere, {{-3.0, 1.0 - 1e-7, 0.0}, {1.0, 0.0, 0.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == Approx(3.0 - std::sqrt(2e-7 - 1e-14)).epsilon(1e-12));
    const auto round_cube = make_superellipsoid(0.1, 0.1);
    // Along the edge direction, just inside the rounded edge region.
    const glm::dvec3 p = surface_point({0.1, 0.1}, glm::normalize(glm::dvec3(1.0, 1.0, 0.0)));
    const glm::dvec3 inward = p * (1.0 - 1e-8);
    const auto edge =
        geo::intersect(round_cube, {inward + glm::dvec3(0, 0, -5), {0, 0, 1}}, 0.0, kInf);
    REQUIRE(edge);
    CHECK(edge->s > 4.0);
    CHECK_FALSE(geo::intersect(round_cube, {p * (1.0 + 1e-8) + glm::dvec3(0, 0, -5), {0, 0, 1}},
                               0.0, kInf));
}

TEST_CASE("superellipsoid: normals are the function's gradient", "[geometry][superellipsoid]") {
    Random random(7);
    for (const auto& s : kShapes) {
        const auto g = make_superellipsoid(s.e, s.n);
        int checked = 0;
        for (int i = 0; i < 400; ++i) {
            const glm::dvec3 p = surface_point(s, random.unit_vector());
            const glm::dvec3 n = geo::superellipsoid_normal(g, p);
            REQUIRE(finite(n));
            CHECK(std::fabs(glm::length(n) - 1.0) < 1e-12);
            // Outward: a step along it leaves the solid.
            CHECK(glm::dot(n, p) > 0.0);
            // Against finite differences where the gradient is smooth at the
            // difference's scale (away from creases of the small exponents).
            const double h = 1e-7;
            const glm::dvec3 fd = reference_gradient(s, p, h);
            const glm::dvec3 fd2 = reference_gradient(s, p, 2.0 * h);
            if (!finite(fd) || glm::length(fd) == 0.0) continue;
            if (glm::length(glm::normalize(fd) - glm::normalize(fd2)) > 1e-6) continue;
            ++checked;
            CHECK(glm::length(n - glm::normalize(fd)) < 1e-5);
        }
        INFO("e " << s.e << " n " << s.n);
        CHECK(checked > 100);
    }
}

TEST_CASE("superellipsoid: inside against the function", "[geometry][superellipsoid]") {
    Random random(9);
    for (const auto& s : kShapes) {
        const auto g = make_superellipsoid(s.e, s.n);
        for (int i = 0; i < 3000; ++i) {
            const glm::dvec3 p = random.in_cube(1.3);
            const long double f = reference(s, p);
            if (std::fabs(f) < 1e-9L) continue;
            CHECK(geo::inside(g, p) == (f < 0.0L));
        }
    }
}

TEST_CASE("superellipsoid: bounds and surface_may_meet", "[geometry][superellipsoid]") {
    Random random(13);
    for (const auto& s : kShapes) {
        const auto g = make_superellipsoid(s.e, s.n);
        const Box3 bounds = geo::object_bounds(g);
        for (int i = 0; i < 500; ++i) {
            const glm::dvec3 p = surface_point(s, random.unit_vector());
            CHECK(geo::contains(bounds, p));
            // A point box on the surface, and small boxes around it.
            CHECK(geo::surface_may_meet(g, {p, p}));
            const double r = random.log_uniform(1e-9, 0.3);
            CHECK(geo::surface_may_meet(g, {p - r * random.uniform(), p + r * random.uniform()}));
        }
        // Boxes well inside or well outside do not meet the surface.
        for (int i = 0; i < 500; ++i) {
            const glm::dvec3 c = random.in_cube(1.5);
            const double r = random.log_uniform(1e-4, 0.1);
            const Box3 box{c - r, c + r};
            bool any_in = false, any_out = false;
            for (const auto& corner : geo::corners(box)) {
                (reference(s, corner) <= 0.0L ? any_in : any_out) = true;
            }
            if (any_in && any_out) CHECK(geo::surface_may_meet(g, box));
        }
        CHECK_FALSE(geo::surface_may_meet(g, {glm::dvec3(1.1), glm::dvec3(2.0)}));
        if (s.e >= 0.05 && s.n >= 0.05)
            CHECK_FALSE(geo::surface_may_meet(g, {glm::dvec3(-0.01), glm::dvec3(0.01)}));
    }
}

TEST_CASE("superellipsoid: volume", "[geometry][superellipsoid]") {
    CHECK(geo::superellipsoid_volume(make_superellipsoid(1.0, 1.0)) ==
          Approx(4.0 * kPi / 3.0).epsilon(1e-12));
    CHECK(geo::superellipsoid_volume(make_superellipsoid(0.0, 0.0)) == Approx(8.0).epsilon(1e-12));
    CHECK(geo::superellipsoid_volume(make_superellipsoid(2.0, 2.0)) ==
          Approx(4.0 / 3.0).epsilon(1e-12));
    CHECK(geo::superellipsoid_volume(make_superellipsoid(-1.0, 2.0)) == -1.0);
    Random random(17);
    for (const auto& s : kShapes) {
        const auto g = make_superellipsoid(s.e, s.n);
        int in = 0;
        const int n = 200000;
        for (int i = 0; i < n; ++i) in += reference(s, random.in_cube(1.0)) <= 0.0L;
        const double mc = 8.0 * in / n;
        INFO("e " << s.e << " n " << s.n);
        CHECK(geo::superellipsoid_volume(g) == Approx(mc).margin(0.03));
    }
}

TEST_CASE("superellipsoid: rays from far away", "[geometry][superellipsoid]") {
    Random random(19);
    for (const auto& s : kShapes) {
        const auto g = make_superellipsoid(s.e, s.n);
        for (int i = 0; i < 100; ++i) {
            const glm::dvec3 p = surface_point(s, random.unit_vector());
            const glm::dvec3 n = geo::superellipsoid_normal(g, p);
            glm::dvec3 away = random.unit_vector();
            if (glm::dot(away, n) < 0.3) continue;  // from the front, not grazing
            const glm::dvec3 origin = p + 1e6 * away;
            const glm::dvec3 dir = p - origin;
            const auto hit = geo::intersect(g, {origin, dir}, 0.0, kInf);
            // The rounded ray passes p within ~1e-10; the convex shapes are hit
            // at p, the others at p or before.
            REQUIRE(hit);
            CHECK(well_formed(*hit));
            CHECK(hit->s <= 1.0 + 1e-15);
            if (s.e <= 2.0 && s.n <= 2.0) CHECK(glm::length(hit->point - p) < 1e-7);
            CHECK(std::fabs((double)reference(s, hit->point)) < 1e-6);
        }
    }
}

TEST_CASE("superellipsoid: no NaN for extreme rays and exponents", "[geometry][superellipsoid]") {
    Random random(23);
    const std::vector<Exponents> extreme = {{1e-300, 1e-300}, {1e-12, 7.0}, {50.0, 1e-9},
                                            {1e6, 1e6},       {1e300, 1.0}, {0.0, 3.0}};
    std::vector<Exponents> all = kShapes;
    all.insert(all.end(), extreme.begin(), extreme.end());
    const double scales[] = {1e-300, 1e-20, 1.0, 1e20, 1e300};
    for (const auto& s : all) {
        const auto g = make_superellipsoid(s.e, s.n);
        for (int i = 0; i < 300; ++i) {
            const glm::dvec3 origin = random.unit_vector() * scales[random.integer(0, 4)];
            glm::dvec3 dir = random.unit_vector() * scales[random.integer(0, 4)];
            if (i % 5 == 0) dir[random.integer(0, 2)] = 0.0;
            if (i % 7 == 0) dir = -origin;
            const auto hit = geo::intersect(g, {origin, dir}, 0.0, kInf);
            if (hit) CHECK(well_formed(*hit));
            const glm::dvec3 n = geo::superellipsoid_normal(g, origin);
            CHECK(finite(n));
            (void)geo::inside(g, origin);
            (void)geo::surface_may_meet(g, {origin, origin + glm::abs(dir)});
        }
        // Hits on every extreme shape's axes (its surface passes (1, 0, 0)
        // and (0, 0, 1) whatever the exponents).
        if (g.valid) {
            const auto x = geo::intersect(g, {{5.0, 0.0, 0.0}, {-1.0, 0.0, 0.0}}, 0.0, kInf);
            const auto z = geo::intersect(g, {{0.0, 0.0, -5.0}, {0.0, 0.0, 1.0}}, 0.0, kInf);
            REQUIRE(x);
            REQUIRE(z);
            CHECK(x->s == Approx(4.0).epsilon(1e-12));
            CHECK(z->s == Approx(4.0).epsilon(1e-12));
            CHECK(x->normal.x == Approx(1.0));
            CHECK(z->normal.z == Approx(-1.0));
        }
    }
}
