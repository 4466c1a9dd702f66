// The shared numerics of runtime/geometry: exact-sign products, the stable
// quadratic, the compensated dot product, POV-Ray's outline rule, and
// offset_ray (Ray Tracing Gems ch. 6 in double): secondary rays started from
// offset hit points never hit the surface they leave, at any scale or
// distance from the origin.
#include <vector>

#include "geometry_test_support.hpp"
#include "runtime/geometry/offset_ray.hpp"
#include "runtime/geometry/outline.hpp"
#include "runtime/geometry/stable_arithmetic.hpp"
#include "runtime/objects/box/box_geometry.hpp"
#include "runtime/objects/cylinder/cylinder_geometry.hpp"
#include "runtime/objects/sphere/sphere_geometry.hpp"
#include "runtime/objects/torus/torus_geometry.hpp"
#include "runtime/objects/triangle/triangle_geometry.hpp"

using namespace geometry_test;
namespace geo = hexant::runtime::geometry;

TEST_CASE("geometry numerics: exact signs, stable roots, compensated dots", "[runtime][geometry]") {
    Random random(71);
    for (int i = 0; i < 20000; ++i) {
        // Nearly cancelling products of numbers with 31 significant bits, so
        // that the long double products (62 bits) are exact and the
        // reference difference is rounded once: its sign is exact.
        const int ea = random.integer(-300, 300), eb = random.integer(-300, 300);
        const double ai = std::round(random.uniform(-1.0, 1.0) * 0x1p31);
        const double bi = std::round(random.uniform(-1.0, 1.0) * 0x1p31);
        const double ci = ai + random.integer(-2, 2), di = bi + random.integer(-2, 2);
        const double a = std::ldexp(ai, ea), b = std::ldexp(bi, eb);
        const double c = std::ldexp(ci, ea), d = std::ldexp(di, eb);
        const long double exact = (long double)a * b - (long double)c * d;
        const double got = geo::difference_of_products(a, b, c, d);
        CHECK((got > 0) == (exact > 0));
        CHECK((got < 0) == (exact < 0));
        if (exact != 0) CHECK(std::fabs((got - (double)exact) / (double)exact) < 4.0 * kEps);
    }
    // The quadratic: roots from the stable pair, against long double.
    for (int i = 0; i < 20000; ++i) {
        const double r1 = random.uniform(-1.0, 1.0) * random.log_uniform(1e-8, 1e8);
        const double r2 = random.uniform(-1.0, 1.0) * random.log_uniform(1e-8, 1e8);
        // A (t - r1)(t - r2) = A t^2 - A (r1 + r2) t + A r1 r2.
        const double A = random.log_uniform(1e-3, 1e3);
        const double B = -0.5 * A * (r1 + r2), C = A * r1 * r2;
        const long double disc_ld = (long double)B * B - (long double)A * C;
        const geo::QuadraticRoots roots = geo::solve_quadratic(A, B, C, (double)disc_ld);
        REQUIRE(roots.count == 2);
        const long double sq = std::sqrt(std::max(disc_ld, 0.0L));
        const long double lo = (-(long double)B - sq) / A, hi = (-(long double)B + sq) / A;
        const double scale = std::max(std::fabs(r1), std::fabs(r2));
        CHECK(std::fabs(roots.t[0] - (double)lo) <= 1e-12 * scale + 1e-3 * std::fabs((double)lo));
        CHECK(std::fabs(roots.t[1] - (double)hi) <= 1e-12 * scale + 1e-3 * std::fabs((double)hi));
        // The small root in relative terms, where b^2 - 4ac formulas fail.
        const double small = std::fabs(r1) < std::fabs(r2) ? r1 : r2;
        if (std::fabs(small) < 1e-6 * scale) {
            const double got =
                std::fabs(roots.t[0]) < std::fabs(roots.t[1]) ? roots.t[0] : roots.t[1];
            CHECK(std::fabs(got - small) <= 1e-9 * std::fabs(small));
        }
    }
    // A = 0: one root; a negative discriminant: none; B = disc = 0: a double root at 0.
    auto linear = geo::solve_quadratic(0.0, 1.0, -4.0, 1.0);
    REQUIRE(linear.count == 1);
    CHECK(linear.t[0] == 2.0);
    CHECK(geo::solve_quadratic(1.0, 0.0, 1.0, -1.0).count == 0);
    auto twice = geo::solve_quadratic(1.0, 0.0, 0.0, 0.0);
    REQUIRE(twice.count == 1);
    CHECK(twice.t[0] == 0.0);
    // c - dot(a, b) far from the origin, against long double: all numbers
    // on a grid of 2^-42 below 2^22, so that products and sums are exact in
    // long double's 64 bits.
    auto grid = [&](double scale_bits, double value_bits) {
        return std::ldexp(std::round(random.uniform(-1.0, 1.0) * std::ldexp(1.0, (int)value_bits)),
                          (int)scale_bits);
    };
    for (int i = 0; i < 20000; ++i) {
        const glm::dvec3 a{grid(-11, 31), grid(-11, 31), grid(-11, 31)};  // up to 1e6
        const glm::dvec3 b{grid(-31, 31), grid(-31, 31), grid(-31, 31)};  // up to 1
        const long double dot =
            (long double)a.x * b.x + (long double)a.y * b.y + (long double)a.z * b.z;
        const double c =
            std::ldexp(std::round(std::ldexp((double)dot + random.uniform(-1.0, 1.0), 42)), -42);
        const long double exact = (long double)c - dot;
        CHECK(std::fabs(geo::compensated_offset(c, a, b) - (double)exact) <=
              2.0 * kEps * std::fabs((double)exact) + 1e-30);
    }
}

TEST_CASE("geometry outlines: POV-Ray's closing rule", "[runtime][geometry]") {
    auto edges_of = [](const std::vector<glm::dvec2>& points) {
        std::vector<std::pair<std::size_t, std::size_t>> edges;
        geo::for_each_outline_edge(points.data(), points.size(), [&](std::size_t i, std::size_t j) {
            edges.push_back({i, j});
        });
        return edges;
    };
    using E = std::vector<std::pair<std::size_t, std::size_t>>;
    // Two closed outlines: no edge joins them.
    CHECK(edges_of({{0, 0}, {1, 0}, {0, 1}, {0, 0}, {5, 5}, {6, 5}, {5, 6}, {5, 5}}) ==
          E{{0, 1}, {1, 2}, {2, 0}, {4, 5}, {5, 6}, {6, 4}});
    // The last outline left open is closed.
    CHECK(edges_of({{0, 0}, {1, 0}, {0, 1}, {0, 0}, {5, 5}, {6, 5}, {5, 6}}) ==
          E{{0, 1}, {1, 2}, {2, 0}, {4, 5}, {5, 6}, {6, 4}});
    // A point repeated in a row makes no edge.
    CHECK(edges_of({{0, 0}, {1, 0}, {1, 0}, {0, 1}}) == E{{0, 1}, {2, 3}, {3, 0}});
    const std::vector<glm::dvec2> ring = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 0},
                                          {1, 1}, {3, 1}, {3, 3}, {1, 3}, {1, 1}};
    auto same = [](const glm::dvec2& q) { return q; };
    CHECK(geo::inside_even_odd(ring.data(), ring.size(), same, {0.5, 0.5}));
    CHECK_FALSE(geo::inside_even_odd(ring.data(), ring.size(), same, {2.0, 2.0}));
    CHECK_FALSE(geo::inside_even_odd(ring.data(), ring.size(), same, {5.0, 2.0}));
    CHECK(geo::region_meets_rectangle(ring.data(), ring.size(), same, {1.5, 1.5}, {2.5, 3.5}));
    CHECK_FALSE(
        geo::region_meets_rectangle(ring.data(), ring.size(), same, {1.5, 1.5}, {2.5, 2.5}));
    CHECK(geo::region_meets_rectangle(ring.data(), ring.size(), same, {0.2, 0.2}, {0.3, 0.3}));
}

TEST_CASE("offset_ray: ulp steps far out, steps of the point's scale near zero",
          "[runtime][geometry]") {
    // Far from zero: 256 ulps per unit of normal, away from the surface.
    const glm::dvec3 p{1e6, -1e6, 3.0};
    const glm::dvec3 moved = geo::offset_ray(p, {1.0, 0.0, 0.0});
    CHECK(moved.x > p.x);
    CHECK(moved.x == Approx(p.x + 256.0 * (std::nextafter(p.x, 2e6) - p.x)).epsilon(1e-12));
    CHECK(moved.y == p.y);
    CHECK(moved.z == p.z);
    const glm::dvec3 moved_neg = geo::offset_ray(p, {0.0, 1.0, -1.0});
    CHECK(moved_neg.y > p.y);  // toward +y although y is negative
    CHECK(moved_neg.z < p.z);
    // Near zero (below 1/32 of the largest coordinate): 2^-45 of that
    // coordinate per unit of normal.
    const glm::dvec3 small = geo::offset_ray({1e-20, 0.0, -1.0}, {1.0, 1.0, 0.0});
    CHECK(small.x == 1e-20 + 0x1p-45);
    CHECK(small.y == 0x1p-45);
    CHECK(small.z == -1.0);
    const glm::dvec3 large = geo::offset_ray({1e-20, 0.0, -1e6}, {0.0, 1.0, 0.0});
    CHECK(large.y == 0x1p-45 * 1e6);
    // The same point at any power-of-two scale moves the same relative way:
    // nothing in the step is absolute (a scene drawn 2^-60 times smaller
    // starts its rays at the same relative places).
    for (const int e : {-1000, -60, -1, 0, 7, 60, 1000}) {
        const glm::dvec3 q{0.75, 1e-3, -0.02};
        const glm::dvec3 n = glm::normalize(glm::dvec3{0.3, -0.5, 0.8});
        const glm::dvec3 unit = geo::offset_ray(q, n);
        const glm::dvec3 scaled = geo::offset_ray(std::ldexp(1.0, e) * q, n);
        for (int k = 0; k < 3; ++k) CHECK(scaled[k] == std::ldexp(unit[k], e));
    }
    // The top of the range: no Inf.
    const glm::dvec3 top = geo::offset_ray({1.7976931348623157e308, 0.0, 0.0}, {1.0, 0.0, 0.0});
    CHECK(std::isfinite(top.x));
}

namespace {

// Hits of random rays on a shape; from each, a ray leaving outward (offset
// along the outward normal) must not meet the surface near where it starts,
// and one entering (offset along the inward normal) must travel into the
// solid before its next hit.
template <class G>
void check_no_self_hits(const char* name, const G& g, const glm::dvec3& centre, double size,
                        bool convex, Random& random) {
    INFO(name);
    int tested = 0;
    for (int i = 0; i < 4000 && tested < 1500; ++i) {
        const glm::dvec3 origin =
            centre + size * random.log_uniform(2.0, 1e6) * random.unit_vector();
        const glm::dvec3 target = centre + 0.8 * size * random.in_cube(1.0);
        const auto hit = intersect(g, Ray3{origin, target - origin}, 0.0, kInf);
        if (!hit) continue;
        ++tested;
        const glm::dvec3 n = hit->normal;
        // Outgoing: random in the outward hemisphere, down to grazing.
        glm::dvec3 out = random.unit_vector();
        if (glm::dot(out, n) < 0.0) out = -out;
        if (i % 4 == 0) out = glm::normalize(out - glm::dot(out, n) * n + 1e-4 * n);
        const glm::dvec3 start = geo::offset_ray(hit->point, n);
        const auto again = intersect(g, Ray3{start, out}, 0.0, kInf);
        if (convex) {
            CHECK_FALSE(again.has_value());
        } else if (again) {
            CHECK(glm::length(again->point - hit->point) > 1e-9 * size);
        }
        // Transmitted: into the solid, must cross it before the next hit.
        glm::dvec3 in = random.unit_vector();
        if (glm::dot(in, n) > 0.0) in = -in;
        const glm::dvec3 inside_start = geo::offset_ray(hit->point, -n);
        const auto through = intersect(g, Ray3{inside_start, in}, 0.0, kInf);
        if (through) CHECK(glm::length(through->point - hit->point) > 1e-9 * size);
    }
    CHECK(tested > 500);
}

}  // namespace

TEST_CASE("offset_ray: no self-intersection at any scale or distance", "[runtime][geometry]") {
    Random random(72);
    for (const auto& [size, centre] :
         {std::pair{1.0, glm::dvec3(0.0)}, std::pair{1e-6, glm::dvec3(0.0)},
          std::pair{1e-6, glm::dvec3(0.3, -0.1, 0.2)}, std::pair{1e6, glm::dvec3(1e6, 2e6, -3e6)},
          std::pair{1.0, glm::dvec3(1e6, 2e6, -3e6)}}) {
        check_no_self_hits("sphere", geo::SphereGeometry{centre, size}, centre, size, true, random);
        check_no_self_hits(
            "box", geo::BoxGeometry{centre - size, centre + glm::dvec3(0.5, 1.0, 2.0) * size},
            centre, size, true, random);
        check_no_self_hits(
            "cylinder",
            geo::CylinderGeometry{centre - size * glm::dvec3(0.1, 1.0, 0.2),
                                  centre + size * glm::dvec3(0.1, 1.0, 0.2), 0.7 * size, false},
            centre, size, true, random);
        check_no_self_hits("triangle",
                           geo::TriangleGeometry{centre + size * glm::dvec3(-1.0, -1.0, 0.2),
                                                 centre + size * glm::dvec3(1.0, -0.5, -0.1),
                                                 centre + size * glm::dvec3(0.0, 1.0, 0.3)},
                           centre, size, true, random);
        if (centre == glm::dvec3(0.0)) {
            check_no_self_hits("torus", geo::TorusGeometry{size, 0.3 * size}, centre, size, false,
                               random);
        }
    }
}

#include "runtime/objects/cylinder/cone_geometry.hpp"
#include "runtime/objects/disc/disc_geometry.hpp"
#include "runtime/objects/plane/plane_geometry.hpp"
#include "runtime/objects/polygon/polygon_geometry.hpp"
#include "runtime/objects/prism/prism_geometry.hpp"
#include "runtime/objects/triangle/smooth_triangle_geometry.hpp"

namespace {

// Numbers of any magnitude the doubles allow, either sign, sometimes zero.
double wild(Random& random) {
    if (random.uniform() < 0.05) return 0.0;
    const double m = random.log_uniform(1e-300, 1e300);
    return random.uniform() < 0.5 ? -m : m;
}

glm::dvec3 wild_vector(Random& random) {
    return {wild(random), wild(random), wild(random)};
}

// Half the rays are aimed at a point of the shape, so that hits happen.
template <class G>
int fuzz_one(const G& g, const glm::dvec3& aim, Random& random) {
    Ray3 ray{wild_vector(random), wild_vector(random)};
    if (random.uniform() < 0.5) {
        ray.origin = aim + wild_vector(random);
        ray.direction = (aim - ray.origin) * random.log_uniform(1e-100, 1e100);
    }
    const double s_min = random.uniform() < 0.5 ? 0.0 : -kInf;
    const auto hit = intersect(g, ray, s_min, kInf);
    if (hit) {
        CHECK(well_formed(*hit));
        CHECK(hit->s > s_min);
    }
    const glm::dvec3 p = wild_vector(random);
    (void)inside(g, p);
    const glm::dvec3 q = wild_vector(random);
    (void)surface_may_meet(g, Box3{glm::min(p, q), glm::max(p, q)});
    return hit ? 1 : 0;
}

}  // namespace

TEST_CASE("geometry: wild inputs never give NaN or Inf", "[runtime][geometry]") {
    Random random(73);
    int hits = 0;
    for (int i = 0; i < 3000; ++i) {
        const geo::SphereGeometry sphere{wild_vector(random), wild(random)};
        hits += fuzz_one(sphere, sphere.center, random);
        const geo::BoxGeometry box{wild_vector(random), wild_vector(random)};
        hits += fuzz_one(box, 0.5 * box.corner1 + 0.5 * box.corner2, random);
        const geo::PlaneGeometry plane{wild_vector(random), wild(random)};
        hits += fuzz_one(plane, wild_vector(random), random);
        const geo::TriangleGeometry triangle{wild_vector(random), wild_vector(random),
                                             wild_vector(random)};
        hits +=
            fuzz_one(triangle, triangle.p1 / 3.0 + triangle.p2 / 3.0 + triangle.p3 / 3.0, random);
        const geo::SmoothTriangleGeometry smooth{wild_vector(random), wild_vector(random),
                                                 wild_vector(random), wild_vector(random),
                                                 wild_vector(random), wild_vector(random)};
        hits += fuzz_one(smooth, smooth.p1 / 3.0 + smooth.p2 / 3.0 + smooth.p3 / 3.0, random);
        const geo::DiscGeometry disc{wild_vector(random), wild_vector(random), wild(random),
                                     wild(random)};
        hits += fuzz_one(disc, disc.center, random);
        const geo::CylinderGeometry cylinder{wild_vector(random), wild_vector(random), wild(random),
                                             random.uniform() < 0.5};
        hits += fuzz_one(cylinder, 0.5 * cylinder.base + 0.5 * cylinder.cap, random);
        const geo::ConeGeometry cone{wild_vector(random), wild(random), wild_vector(random),
                                     wild(random), random.uniform() < 0.5};
        hits += fuzz_one(cone, 0.5 * cone.base + 0.5 * cone.cap, random);
        const geo::TorusGeometry torus{wild(random), wild(random)};
        hits += fuzz_one(torus, glm::dvec3(torus.major, 0.0, 0.0), random);
        geo::PolygonGeometry polygon;
        for (int k = 0; k < 5; ++k) polygon.points.push_back(wild_vector(random));
        polygon.points.push_back(polygon.points.front());
        hits += fuzz_one(
            polygon, polygon.points[0] / 3.0 + polygon.points[1] / 3.0 + polygon.points[2] / 3.0,
            random);
        geo::PrismGeometry prism;
        prism.height1 = wild(random);
        prism.height2 = wild(random);
        prism.open = random.uniform() < 0.5;
        for (int k = 0; k < 5; ++k) prism.points.push_back({wild(random), wild(random)});
        hits += fuzz_one(prism, glm::dvec3(prism.points[0].x, prism.height1, prism.points[0].y),
                         random);
    }
    CHECK(hits > 1000);  // the aimed half does meet shapes
}
