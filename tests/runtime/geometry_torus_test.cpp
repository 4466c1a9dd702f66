// Static ray/torus geometry: analytic hits, rays grazing the inner and outer
// equators (pairs of close roots that a quartic solver tends to lose), every
// sign change of a densely sampled long double D along random rays found,
// rays aimed at sampled surface points for radii 1e-6 to 1e6 (major/minor up
// to 1e12) from 1e6 away, inside() against the quartic's sign, and
// surface_may_meet around surface points.
#include <vector>

#include "geometry_test_support.hpp"
#include "runtime/objects/torus/torus_geometry.hpp"

using namespace geometry_test;
using hexant::runtime::geometry::TorusGeometry;

namespace {

SurfaceSample sample_torus(const TorusGeometry& g, Random& random) {
    const double theta = random.uniform(0.0, 2.0 * kPi), phi = random.uniform(0.0, 2.0 * kPi);
    const glm::dvec3 n{std::cos(phi) * std::cos(theta), std::sin(phi),
                       std::cos(phi) * std::sin(theta)};
    const double rho = g.major + g.minor * std::cos(phi);
    SurfaceSample q{{rho * std::cos(theta), g.minor * std::sin(phi), rho * std::sin(theta)}, n};
    q.curvature_radius = g.minor;
    return q;
}

// |distance to the core circle - minor|, in long double.
double torus_residual(const TorusGeometry& g, const glm::dvec3& p) {
    const long double x = p.x, y = p.y, z = p.z;
    const long double e = std::sqrt(x * x + z * z) - g.major;
    return static_cast<double>(std::fabs(std::sqrt(e * e + y * y) - g.minor));
}

// The quartic's sign: (|p|^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + z^2) <= 0 inside.
bool quartic_inside(const TorusGeometry& g, const glm::dvec3& p) {
    const long double x = p.x, y = p.y, z = p.z, R = g.major, r = g.minor;
    const long double a = x * x + y * y + z * z + R * R - r * r;
    return a * a - 4.0L * R * R * (x * x + z * z) <= 0.0L;
}

// All hits along a ray, in order.
std::vector<double> all_hits(const TorusGeometry& g, const Ray3& ray) {
    std::vector<double> hits;
    double s = -kInf;
    while (auto hit = intersect(g, ray, s, kInf)) {
        REQUIRE(well_formed(*hit));
        REQUIRE(hit->s > s);
        hits.push_back(hit->s);
        s = hit->s;
        if (hits.size() > 8) break;
    }
    return hits;
}

}  // namespace

TEST_CASE("torus: analytic hits, normals, uv", "[runtime][geometry]") {
    const TorusGeometry g{2.0, 0.5};
    // Along the x axis from far: the tube at x = -2.5, -1.5, 1.5, 2.5.
    const Ray3 ray{{-10.0, 0.0, 0.0}, {1.0, 0.0, 0.0}};
    const std::vector<double> hits = all_hits(g, ray);
    REQUIRE(hits.size() == 4);
    CHECK(hits[0] == Approx(7.5).epsilon(1e-15));
    CHECK(hits[1] == Approx(8.5).epsilon(1e-15));
    CHECK(hits[2] == Approx(11.5).epsilon(1e-15));
    CHECK(hits[3] == Approx(12.5).epsilon(1e-15));
    auto hit = intersect(g, ray, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->normal.x == Approx(-1.0));
    CHECK(hit->part == 0);
    // POV-Ray's uv: at (-2.5, 0, 0): u = 1 - (atan2(0, -2.5) + pi) / 2pi = 0, v = 0.5.
    CHECK(std::fmod(hit->uv.x, 1.0) == Approx(0.0).margin(1e-12));
    CHECK(hit->uv.y == Approx(0.5));
    // Second hit: the inner side of the tube, normal toward the axis.
    hit = intersect(g, ray, hits[0], kInf);
    REQUIRE(hit);
    CHECK(hit->normal.x == Approx(1.0));
    // From above through the tube: y = 0.5 top, normal +y.
    hit = intersect(g, Ray3{{2.0, 5.0, 0.0}, {0.0, -2.0, 0.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == Approx(2.25).epsilon(1e-15));
    CHECK(hit->normal.y == Approx(1.0));
    CHECK(hit->uv.y == Approx(0.75));
    // Through the hole along y: nothing.
    CHECK_FALSE(intersect(g, Ray3{{0.0, 5.0, 0.0}, {0.0, -1.0, 0.0}}, -kInf, kInf));
    CHECK(inside(g, {2.0, 0.4, 0.0}));
    CHECK_FALSE(inside(g, {0.0, 0.0, 0.0}));
    const Box3 b = object_bounds(g);
    CHECK(b.lo == glm::dvec3(-2.5, -0.5, -2.5));
    CHECK(b.hi == glm::dvec3(2.5, 0.5, 2.5));
    CHECK_FALSE(intersect(TorusGeometry{1.0, 0.0}, ray, 0.0, kInf));
}

// a + b - c for doubles with b small and a + b close to c, in long double
// without the rounding of a + b (two-sum keeps its error exactly).
long double exact_gap(double a, double b, double c) {
    const double sum = a + b;
    const double z = sum - a;
    const double error = (a - (sum - z)) + (b - z);
    return ((long double)sum - c) + error;
}

TEST_CASE("torus: grazing the inner and outer equators", "[runtime][geometry]") {
    for (const auto& [R, r] : {std::pair{1.0, 0.25}, std::pair{1e6, 1e-6}, std::pair{1e-6, 3e-7}}) {
        const TorusGeometry g{R, r};
        for (const double rel : {1e-3, 1e-6, 1e-9, 1e-12, -1e-12, -1e-9, -1e-6, -1e-3}) {
            INFO("R " << R << " r " << r << " offset " << rel);
            // Lines in the plane y = 0 at x = c, along z, from far: c just
            // inside or outside the inner equator (rho = R - r) and the outer
            // one (rho = R + r). The reference roots z = +-sqrt(rho^2 - c^2)
            // take the gap rho - c exactly from the rounded c.
            const double far = 4.0 * (R + r);
            const double delta = rel * r;
            // e = rho - R is good to ulps of itself, about r: the pair's
            // half separation z is then good to c * that / z.
            const double e_error = 16.0 * kEps * r;
            for (const bool inner_equator : {true, false}) {
                const double c = inner_equator ? (R - r) - delta : (R + r) - delta;
                const Ray3 ray{{c, 0.0, -far}, {0.0, 0.0, 1.0}};
                const std::vector<double> hits = all_hits(g, ray);
                const long double gap_outer = exact_gap(R, r, c);   // R + r - c
                const long double gap_inner = exact_gap(R, -r, c);  // R - r - c
                const long double outer_z =
                    gap_outer > 0 ? std::sqrt(gap_outer * ((long double)R + r + c)) : 0;
                const long double inner_z =
                    gap_inner > 0 ? std::sqrt(gap_inner * ((long double)R - r + c)) : 0;
                const long double gap = inner_equator ? gap_inner : gap_outer;
                if (std::fabs((double)gap) < 4.0 * e_error) continue;  // tangent within rounding
                const std::size_t expected = (gap_outer > 0 ? 2 : 0) + (gap_inner > 0 ? 2 : 0);
                REQUIRE(hits.size() == expected);
                if (expected == 0) continue;
                const double s_grain = 4.0 * kEps * far;  // the rounding of s near far
                auto close = [&](double measured, long double z) {
                    const double tolerance = c * e_error / (double)z + s_grain;
                    return std::fabs(measured - (double)z) <= tolerance;
                };
                CHECK(close(far - hits.front(), outer_z));
                CHECK(close(hits.back() - far, outer_z));
                if (expected == 4) {
                    CHECK(close(far - hits[1], inner_z));
                    CHECK(close(hits[2] - far, inner_z));
                }
            }
        }
    }
}

TEST_CASE("torus: no sign change of D along a ray is skipped", "[runtime][geometry]") {
    Random random(41);
    for (const auto& [R, r] : {std::pair{1.0, 0.25}, std::pair{1.0, 0.02}, std::pair{0.2, 0.5}}) {
        const TorusGeometry g{R, r};
        for (int i = 0; i < 300; ++i) {
            // Rays through a random point near the torus, many nearly tangent.
            const glm::dvec3 through = sample_torus(g, random).point + random.in_cube(0.05 * r);
            const glm::dvec3 dir = random.unit_vector();
            const double reach = 2.0 * (R + r) + 1.0;
            const Ray3 ray{through - reach * dir, dir};
            const std::vector<double> hits = all_hits(g, ray);
            // Dense long double samples of D along the chord [0, 2 reach].
            constexpr int kSamples = 4000;
            auto D = [&](double s) {
                const glm::dvec3 p = ray.origin + s * ray.direction;
                const long double x = p.x, y = p.y, z = p.z;
                const long double e = std::sqrt(x * x + z * z) - g.major;
                return e * e + y * y - (long double)g.minor * g.minor;
            };
            long double previous = D(0.0);
            for (int k = 1; k <= kSamples; ++k) {
                const double s0 = 2.0 * reach * (k - 1) / kSamples, s1 = 2.0 * reach * k / kSamples;
                const long double value = D(s1);
                if ((previous < 0) != (value < 0)) {
                    // A root lies in [s0, s1]: some hit must be there.
                    bool found = false;
                    for (const double h : hits)
                        found = found || (h >= s0 - 1e-12 && h <= s1 + 1e-12);
                    INFO("R " << R << " r " << r << " bracket " << s0 << " " << s1);
                    CHECK(found);
                }
                previous = value;
            }
            for (const double h : hits)
                CHECK(torus_residual(g, ray.origin + h * ray.direction) < 1e-12);
        }
    }
}

TEST_CASE("torus: aimed rays at every scale, inside, may-meet", "[runtime][geometry]") {
    Random random(42);
    struct Case {
        const char* name;
        TorusGeometry g;
        double distance;
    };
    const Case cases[] = {
        {"torus 1, 0.25 near", {1.0, 0.25}, 3.0},
        {"torus 1, 0.25 from 1e6", {1.0, 0.25}, 1e6},
        {"torus 1e-6, 3e-7 from 1e6", {1e-6, 3e-7}, 1e6},
        {"torus 1e6, 2e5 from 1e6", {1e6, 2e5}, 1e6},
        {"torus 1e6, 1e-6 from 1e6", {1e6, 1e-6}, 1e6},
        {"torus 1, 1e-6 from 1e6", {1.0, 1e-6}, 1e6},
        {"torus spindle 0.2, 0.5 near", {0.2, 0.5}, 3.0},
    };
    for (const Case& c : cases) {
        INFO(c.name);
        const TorusGeometry& g = c.g;
        const double size = g.major + g.minor;
        const AimStats stats = aim_at_surface(
            g, [&](Random& rr) { return sample_torus(g, rr); },
            [&](const glm::dvec3& p) { return torus_residual(g, p); }, g.minor, c.distance, false,
            1000, random);
        report(c.name, stats);
        CHECK(stats.grazing_misses <= stats.rays / 50);
        CHECK(stats.max_residual < 16.0 * kEps);
        CHECK(stats.max_point_mismatch < 16.0 * kEps);
        const int random_hits = random_rays_are_finite(g, size, glm::dvec3(0.0), 1000, random);
        if (g.minor > 1e-3 * g.major) CHECK(random_hits > 20);  // thin tubes are rarely met
        if (g.minor < g.major) {  // the spindle's samples include hidden inner points
            boxes_around_surface(
                g, [&](Random& rr) { return sample_torus(g, rr); }, g.minor, 10000, random);
        }
        for (int i = 0; i < 3000; ++i) {
            const glm::dvec3 p = random.in_cube(size);
            if (torus_residual(g, p) < 1e-9 * size) continue;
            // The quartic's sign differs inside a spindle's inner lemon,
            // which is inside the solid but where the quartic is positive.
            const long double x = p.x, y = p.y, z = p.z;
            const long double e = std::sqrt(x * x + z * z) - g.major;
            const bool by_distance = e * e + y * y <= (long double)g.minor * g.minor;
            CHECK(inside(g, p) == (g.minor < g.major ? quartic_inside(g, p) : by_distance));
        }
        // No: in the hole, inside the tube, far away.
        if (g.major > 2.0 * g.minor) {
            const double hole = 0.4 * (g.major - g.minor);
            CHECK_FALSE(surface_may_meet(g, Box3{glm::dvec3(-hole), glm::dvec3(hole)}));
        }
        const glm::dvec3 core(g.major, 0.0, 0.0);
        CHECK_FALSE(surface_may_meet(g, Box3{core - 0.3 * g.minor, core + 0.3 * g.minor}));
        CHECK_FALSE(surface_may_meet(g, Box3{glm::dvec3(2.0 * size), glm::dvec3(3.0 * size)}));
    }
}
