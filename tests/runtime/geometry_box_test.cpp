// Static ray/box and ray/plane geometry: analytic hits, rays parallel to the
// faces (zero direction components, origins on face planes), rays aimed at
// sampled face points at every scale, inside() against the ray parity, and
// surface_may_meet around surface points.
#include "geometry_test_support.hpp"
#include "runtime/geometry/box_queries.hpp"
#include "runtime/objects/box/box_geometry.hpp"
#include "runtime/objects/plane/plane_geometry.hpp"

using namespace geometry_test;
using hexant::runtime::geometry::BoxGeometry;
using hexant::runtime::geometry::PlaneGeometry;

namespace {

SurfaceSample sample_box(const BoxGeometry& g, Random& random) {
    const Box3 b = object_bounds(g);
    const glm::dvec3 size = b.hi - b.lo;
    const int axis = random.integer(0, 2);
    const bool upper = random.uniform() < 0.5;
    SurfaceSample q;
    q.normal = glm::dvec3(0.0);
    q.normal[axis] = upper ? 1.0 : -1.0;
    q.edge_distance = kInf;
    for (int k = 0; k < 3; ++k) {
        if (k == axis) {
            q.point[k] = upper ? b.hi[k] : b.lo[k];
            continue;
        }
        const double f = random.uniform(1e-3, 1.0 - 1e-3);
        q.point[k] = b.lo[k] + f * size[k];
        q.edge_distance = std::min(q.edge_distance, std::min(f, 1.0 - f) * size[k]);
    }
    return q;
}

// The distance to the box's surface, in long double.
double box_residual(const BoxGeometry& g, const glm::dvec3& p) {
    const Box3 b = object_bounds(g);
    long double outside = 0.0L, inside_gap = 1e300L;
    for (int k = 0; k < 3; ++k) {
        const long double below = (long double)b.lo[k] - p[k], above = (long double)p[k] - b.hi[k];
        const long double e = std::max(below, above);
        if (e > 0) outside += e * e;
        inside_gap = std::min(inside_gap, -e);
    }
    return static_cast<double>(outside > 0 ? std::sqrt(outside) : std::max(inside_gap, 0.0L));
}

// Counts the surface crossings along a ray from p: odd exactly inside a
// closed solid (for rays that meet no edge, which random rays do not).
template <class G>
int crossings(const G& g, const glm::dvec3& p, const glm::dvec3& dir) {
    int count = 0;
    double s = 0.0;
    while (auto hit = intersect(g, Ray3{p, dir}, s, kInf)) {
        s = hit->s;
        if (++count > 16) break;
    }
    return count;
}

}  // namespace

TEST_CASE("box: analytic hits, faces, uv", "[runtime][geometry]") {
    const BoxGeometry g{{1.0, 2.0, 3.0}, {-1.0, -2.0, -3.0}};  // corners in any order
    auto hit = intersect(g, Ray3{{-5.0, 0.5, 0.5}, {1.0, 0.0, 0.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == 4.0);
    CHECK(hit->part == 0);
    CHECK(hit->normal == glm::dvec3(-1.0, 0.0, 0.0));
    CHECK(hit->point == glm::dvec3(-1.0, 0.5, 0.5));
    // POV-Ray's cube map on -x: u = z/4, v = 1/3 + y/3 with the box scaled to the unit cube.
    CHECK(hit->uv.x == Approx((0.5 + 3.0) / 6.0 / 4.0));
    CHECK(hit->uv.y == Approx(1.0 / 3.0 + (0.5 + 2.0) / 4.0 / 3.0));
    // From inside: the exit face.
    hit = intersect(g, Ray3{{0.0, 0.0, 0.0}, {0.0, 0.0, -2.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == 1.5);
    CHECK(hit->part == 4);
    CHECK(hit->normal == glm::dvec3(0.0, 0.0, -1.0));
    hit = intersect(g, Ray3{{0.0, 10.0, 0.0}, {0.0, -1.0, 0.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->part == 3);
    CHECK(hit->s == 8.0);
    // The second hit past the first.
    hit = intersect(g, Ray3{{0.0, 10.0, 0.0}, {0.0, -1.0, 0.0}}, 8.0, kInf);
    REQUIRE(hit);
    CHECK(hit->part == 2);
    CHECK(hit->s == 12.0);
    const Box3 b = object_bounds(g);
    CHECK(b.lo == glm::dvec3(-1.0, -2.0, -3.0));
    CHECK(b.hi == glm::dvec3(1.0, 2.0, 3.0));
    CHECK(inside(g, {1.0, 2.0, 3.0}));  // closed
    CHECK_FALSE(inside(g, {1.0, 2.0, 3.0000001}));
}

TEST_CASE("box: rays parallel to faces never give NaN", "[runtime][geometry]") {
    const BoxGeometry g{{-1.0, -1.0, -1.0}, {1.0, 1.0, 1.0}};
    // Along x in the plane of the +y face (origin on the face plane): the
    // closed box is met along the face; no NaN either way.
    for (const double y : {1.0, -1.0, 0.999999, 1.000001}) {
        for (const double z : {0.0, 1.0, -1.0}) {
            const auto hit = intersect(g, Ray3{{-5.0, y, z}, {1.0, 0.0, 0.0}}, 0.0, kInf);
            const bool within = std::fabs(y) <= 1.0 && std::fabs(z) <= 1.0;
            CHECK(hit.has_value() == within);
            if (hit) {
                CHECK(well_formed(*hit));
                CHECK(hit->s == 4.0);
                CHECK(hit->part == 0);
            }
        }
    }
    // Subnormal and huge direction components.
    const auto tiny = intersect(g, Ray3{{-5.0, 0.0, 0.0}, {1.0, 1e-310, -1e-310}}, 0.0, kInf);
    REQUIRE(tiny);
    CHECK(tiny->s == 4.0);
    const auto huge = intersect(g, Ray3{{-5.0, 0.0, 0.0}, {1e300, 0.0, 0.0}}, 0.0, kInf);
    REQUIRE(huge);
    CHECK(huge->s == Approx(4e-300));
    // A flat box (zero thickness) is still hit.
    const BoxGeometry flat{{-1.0, 0.0, -1.0}, {1.0, 0.0, 1.0}};
    const auto f = intersect(flat, Ray3{{0.0, 3.0, 0.0}, {0.0, -1.0, 0.0}}, 0.0, kInf);
    REQUIRE(f);
    CHECK(f->s == 3.0);
}

TEST_CASE("box: rays aimed at face points, parity, may-meet", "[runtime][geometry]") {
    Random random(21);
    struct Case {
        const char* name;
        BoxGeometry g;
        double distance;
    };
    const Case cases[] = {
        {"box unit near", {{-1.0, -0.5, -2.0}, {1.0, 0.5, 2.0}}, 5.0},
        {"box unit from 1e6", {{-1.0, -0.5, -2.0}, {1.0, 0.5, 2.0}}, 1e6},
        {"box 1e-6 at 1 from 1e6", {{1.0, 1.0, 1.0}, {1.000001, 1.000002, 1.000003}}, 1e6},
        {"box 1e6 at 1e6 from 1e6", {{1e6, -2e6, 0.0}, {2e6, -1e6, 3e6}}, 1e6},
    };
    for (const Case& c : cases) {
        INFO(c.name);
        const Box3 b = object_bounds(c.g);
        const double size = half_diagonal(b);
        const AimStats stats = aim_at_surface(
            c.g, [&](Random& r) { return sample_box(c.g, r); },
            [&](const glm::dvec3& p) { return box_residual(c.g, p); }, size, c.distance, true, 2000,
            random);
        report(c.name, stats);
        CHECK(stats.max_residual < 16.0 * kEps);
        CHECK(stats.max_front_s_error < 64.0 * kEps);
        CHECK(stats.max_point_mismatch < 16.0 * kEps);
        CHECK(random_rays_are_finite(c.g, size, centre(b), 3000, random) > 100);
        boxes_around_surface(
            c.g, [&](Random& r) { return sample_box(c.g, r); }, size, 10000, random);
        // Parity along random rays agrees with inside().
        for (int i = 0; i < 2000; ++i) {
            const glm::dvec3 p = centre(b) + 0.7 * (b.hi - b.lo) * random.in_cube(1.0);
            if (box_residual(c.g, p) < 1e-9 * size) continue;
            CHECK(inside(c.g, p) == (crossings(c.g, p, random.unit_vector()) % 2 == 1));
        }
        const glm::dvec3 mid = centre(b), quarter = 0.25 * (b.hi - b.lo);
        CHECK_FALSE(surface_may_meet(c.g, Box3{mid - quarter, mid + quarter}));
        CHECK_FALSE(surface_may_meet(c.g, Box3{b.hi + quarter, b.hi + 2.0 * quarter}));
        CHECK(surface_may_meet(c.g, Box3{mid, b.hi + quarter}));
    }
}

TEST_CASE("plane: hits, parallel rays, inside, may-meet", "[runtime][geometry]") {
    // POV-Ray: the normal is normalised, the distance is not.
    const PlaneGeometry g{{0.0, 2.0, 0.0}, 1.5};
    auto hit = intersect(g, Ray3{{3.0, 10.0, -4.0}, {0.0, -2.0, 0.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == 4.25);
    CHECK(hit->point == glm::dvec3(3.0, 1.5, -4.0));
    CHECK(hit->normal == glm::dvec3(0.0, 1.0, 0.0));
    // From below the normal is not flipped.
    hit = intersect(g, Ray3{{0.0, -1.0, 0.0}, {0.0, 1.0, 0.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->normal == glm::dvec3(0.0, 1.0, 0.0));
    // Parallel rays, in and off the plane: no hit, no NaN.
    CHECK_FALSE(intersect(g, Ray3{{0.0, 1.5, 0.0}, {1.0, 0.0, 0.0}}, -kInf, kInf));
    CHECK_FALSE(intersect(g, Ray3{{0.0, 2.0, 0.0}, {1.0, 0.0, 1.0}}, -kInf, kInf));
    // Nearly parallel: a huge s, never Inf.
    hit = intersect(g, Ray3{{0.0, 2.0, 0.0}, {1.0, -1e-300, 0.0}}, 0.0, kInf);
    if (hit) CHECK(well_formed(*hit));
    CHECK(inside(g, {5.0, 1.5, 7.0}));
    CHECK(inside(g, {5.0, -100.0, 7.0}));
    CHECK_FALSE(inside(g, {5.0, 1.6, 7.0}));
    CHECK_FALSE(inside(PlaneGeometry{{0.0, 0.0, 0.0}, 1.0}, {0.0, 0.0, 0.0}));

    Random random(22);
    for (const double scale : {1e-6, 1.0, 1e6}) {
        const glm::dvec3 n = glm::normalize(glm::dvec3(0.3, -0.9, 0.4));
        const PlaneGeometry tilted{n * 7.0, 0.37 * scale};  // unnormalised normal
        const glm::dvec3 t1 = glm::normalize(glm::cross(n, glm::dvec3(1.0, 0.0, 0.0)));
        const glm::dvec3 t2 = glm::cross(n, t1);
        auto sample = [&](Random& r) {
            return SurfaceSample{
                0.37 * scale * n + r.uniform(-scale, scale) * t1 + r.uniform(-scale, scale) * t2,
                n};
        };
        auto residual = [&](const glm::dvec3& p) {
            const long double d = (long double)p.x * n.x + (long double)p.y * n.y +
                                  (long double)p.z * n.z - 0.37L * scale;
            return static_cast<double>(std::fabs(d));
        };
        for (const double distance : {scale, 1e6}) {
            const AimStats stats =
                aim_at_surface(tilted, sample, residual, scale, distance, true, 2000, random);
            report(scale == 1.0 ? "plane size 1" : "plane size 1e-6 or 1e6", stats);
            CHECK(stats.grazing_misses == 0);
            CHECK(stats.max_residual < 16.0 * kEps);
            CHECK(stats.max_front_s_error < 64.0 * kEps);
        }
        CHECK(random_rays_are_finite(tilted, scale, glm::dvec3(0.0), 3000, random) > 100);
        boxes_around_surface(tilted, sample, scale, 10000, random);
        CHECK_FALSE(surface_may_meet(tilted, Box3{n * scale, n * scale + 0.1 * scale}));
        CHECK_FALSE(surface_may_meet(tilted, Box3{-n * scale - 0.1 * scale, -n * scale}));
    }
}
