// Static ray/sor geometry: POV-Ray's Hermite r^2(y) through the points,
// hits against a dense reference along the ray (sign changes of
// x^2 + z^2 - r^2(y) sampled finely in long double, and the cap discs),
// caps and open, normals against the gradient by finite differences,
// inside() against its definition, rays aimed at sampled surface points at
// every scale, bounds around sampled points, and no NaN for extreme rays.
#include <vector>

#include "geometry_test_support.hpp"
#include "runtime/geometry/box_queries.hpp"
#include "runtime/objects/sor/sor_geometry.hpp"

using namespace geometry_test;
using hexant::runtime::geometry::make_sor;
using hexant::runtime::geometry::SorGeometry;

namespace {

std::vector<glm::dvec2> vase() {
    return {{0.0, -0.5}, {0.6, 0.0}, {1.0, 0.4}, {0.5, 1.0},
            {0.45, 1.3}, {0.9, 1.8}, {0.8, 2.0}, {1.2, 2.5}};
}

// The segment holding y (POV-Ray's inside rule: the first in order).
int segment_of(const SorGeometry& g, double y) {
    for (std::size_t i = 0; i < g.segments.size(); ++i)
        if (y >= g.segments[i].y_lo && y <= g.segments[i].y_hi) return static_cast<int>(i);
    return -1;
}

// x^2 + z^2 - r^2(y) in long double; NaN outside the heights.
long double excess(const SorGeometry& g, glm::dvec3 o, glm::dvec3 u, long double k) {
    const long double x = o.x + k * u.x, y = o.y + k * u.y, z = o.z + k * u.z;
    const int i = segment_of(g, static_cast<double>(y));
    if (i < 0) return std::numeric_limits<long double>::quiet_NaN();
    const auto& s = g.segments[static_cast<std::size_t>(i)];
    return x * x + z * z - (((s.a * y + s.b) * y + s.c) * y + s.d);
}

// The first sign change of the excess (or a cap crossing) by fine sampling.
std::optional<double> reference_hit(const SorGeometry& g, glm::dvec3 o, glm::dvec3 u,
                                    double k_max) {
    std::optional<double> best;
    const int n = 200000;
    long double previous = excess(g, o, u, 0.0L);
    for (int i = 1; i <= n && !best; ++i) {
        const long double k = k_max * i / n;
        const long double e = excess(g, o, u, k);
        if (!std::isnan((double)previous) && !std::isnan((double)e) && (previous > 0) != (e > 0))
            best = static_cast<double>(k);
        previous = e;
    }
    if (!g.open && u.y != 0.0) {
        const double heights[2] = {g.height1, g.height2};
        const double r2[2] = {g.base_radius_squared, g.cap_radius_squared};
        for (int c = 0; c < 2; ++c) {
            const double k = (heights[c] - o.y) / u.y;
            const glm::dvec3 p = o + k * u;
            if (k > 0.0 && p.x * p.x + p.z * p.z <= r2[c] && (!best || k < *best)) best = k;
        }
    }
    return best;
}

double surface_residual(const SorGeometry& g, glm::dvec3 p) {
    const int i = segment_of(g, p.y);
    double best = kInf;
    if (i >= 0) {
        const double r = std::sqrt(std::max(g.segments[static_cast<std::size_t>(i)].r2(p.y), 0.0));
        best = std::fabs(std::hypot(p.x, p.z) - r);
    }
    if (!g.open) {
        const double rho = std::hypot(p.x, p.z);
        if (rho <= std::sqrt(g.base_radius_squared) * (1 + 1e-12))
            best = std::min(best, std::fabs(p.y - g.height1));
        if (rho <= std::sqrt(g.cap_radius_squared) * (1 + 1e-12))
            best = std::min(best, std::fabs(p.y - g.height2));
    }
    return best;
}

}  // namespace

TEST_CASE("sor: r^2 interpolates the points with POV-Ray's slopes", "[geometry][sor]") {
    const auto p = vase();
    const SorGeometry g = make_sor(p, false);
    REQUIRE(g.segments.size() == p.size() - 3);
    for (std::size_t i = 0; i < g.segments.size(); ++i) {
        const auto& s = g.segments[i];
        CHECK(s.r2(p[i + 1].y) == Approx(p[i + 1].x * p[i + 1].x).margin(1e-12));
        CHECK(s.r2(p[i + 2].y) == Approx(p[i + 2].x * p[i + 2].x).margin(1e-12));
        CHECK(
            s.r2_slope(p[i + 1].y) ==
            Approx(2.0 * p[i + 1].x * (p[i + 2].x - p[i].x) / (p[i + 2].y - p[i].y)).margin(1e-11));
        CHECK(s.r2_slope(p[i + 2].y) ==
              Approx(2.0 * p[i + 2].x * (p[i + 3].x - p[i + 1].x) / (p[i + 3].y - p[i + 1].y))
                  .margin(1e-11));
    }
    CHECK(g.height1 == 0.0);
    CHECK(g.height2 == 2.0);
    CHECK(g.base_radius_squared == Approx(0.36));
    CHECK(g.cap_radius_squared == Approx(0.64));
    // POV-Ray's rules: fewer than 4 points, negative radius, heights not rising.
    CHECK(make_sor({{1, 0}, {1, 1}, {1, 2}}, false).segments.empty());
    CHECK(make_sor({{1, 0}, {-1, 1}, {1, 2}, {1, 3}}, false).segments.empty());
    CHECK(make_sor({{1, 0}, {1, 1}, {1, 1}, {1, 3}, {1, 4}}, false).segments.empty());
    CHECK(!make_sor({{1, 5}, {1, 1}, {1, 2}, {1, -3}}, false).segments.empty());  // ends steer only
}

TEST_CASE("sor: first hits against fine sampling, caps and open", "[geometry][sor]") {
    Random random(31);
    for (const bool open : {false, true}) {
        const SorGeometry g = make_sor(vase(), open);
        int hits = 0;
        for (int i = 0; i < 300; ++i) {
            const glm::dvec3 target{random.uniform(-1.0, 1.0), random.uniform(-0.2, 2.2),
                                    random.uniform(-1.0, 1.0)};
            const glm::dvec3 origin = target + random.uniform(2.0, 4.0) * random.unit_vector();
            const glm::dvec3 dir = glm::normalize(target - origin);
            const auto ours = intersect(g, Ray3{origin, dir}, 0.0, kInf);
            const auto ref = reference_hit(g, origin, dir, 8.0);
            INFO("open " << open << " ray " << i);
            if (ours) {
                ++hits;
                REQUIRE(well_formed(*ours));
                INFO("residual " << surface_residual(g, ours->point));
                CHECK(surface_residual(g, ours->point) < 1e-12);
            }
            if (ours && ref) {
                if (std::fabs(glm::dot(ours->normal, dir)) > 0.05)
                    CHECK(std::fabs(ours->s - *ref) < 1e-4);
            } else if (ours || ref) {
                const double k = ours ? ours->s : *ref;
                // Only a graze: the excess hardly changes sign.
                const glm::dvec3 p = origin + k * dir;
                CHECK(surface_residual(g, p) < 1e-3);
            }
        }
        CHECK(hits > 100);
    }
    // Cap from above, base from below, normals; none when open.
    const SorGeometry closed = make_sor(vase(), false), open = make_sor(vase(), true);
    auto hit = intersect(closed, Ray3{{0.1, 5.0, 0.0}, {0.0, -1.0, 0.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == Approx(3.0));
    CHECK(hit->part == 1);
    CHECK(hit->normal.y == 1.0);
    CHECK(hit->uv.y == Approx(2.0 - 0.1 / 0.8));
    hit = intersect(closed, Ray3{{0.1, -5.0, 0.0}, {0.0, 1.0, 0.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->part == 0);
    CHECK(hit->normal.y == -1.0);
    CHECK(hit->uv.y == Approx(0.1 / 0.6 - 1.0));
    hit = intersect(open, Ray3{{0.1, 5.0, 0.0}, {0.0, -1.0, 0.0}}, 0.0, kInf);
    CHECK(!hit);  // straight through the open ends
    // Inside is the closed solid, also when open.
    CHECK(inside(open, {0.0, 1.0, 0.0}));
    CHECK(inside(closed, {0.0, 1.0, 0.0}));
    CHECK(!inside(closed, {0.0, 2.1, 0.0}));
}

TEST_CASE("sor: normals against the gradient, outward", "[geometry][sor]") {
    Random random(8);
    const SorGeometry g = make_sor(vase(), true);
    int checked = 0;
    for (int i = 0; i < 300; ++i) {
        const double y = random.uniform(0.01, 1.99), angle = random.uniform(0.0, 2.0 * kPi);
        const auto& s = g.segments[static_cast<std::size_t>(segment_of(g, y))];
        const double r = std::sqrt(s.r2(y));
        const glm::dvec3 p{r * std::cos(angle), y, r * std::sin(angle)};
        const double h = 1e-6;
        auto f = [&](glm::dvec3 q) { return q.x * q.x + q.z * q.z - s.r2(q.y); };
        const glm::dvec3 grad =
            glm::normalize(glm::dvec3(f(p + glm::dvec3(h, 0, 0)) - f(p - glm::dvec3(h, 0, 0)),
                                      f(p + glm::dvec3(0, h, 0)) - f(p - glm::dvec3(0, h, 0)),
                                      f(p + glm::dvec3(0, 0, h)) - f(p - glm::dvec3(0, 0, h))));
        const auto hit = intersect(g, Ray3{p + 0.3 * grad, -grad}, 0.0, kInf);
        if (!hit || std::fabs(hit->s - 0.3) > 1e-9) continue;
        ++checked;
        CHECK(glm::dot(hit->normal, grad) > 1.0 - 1e-8);
        CHECK(!inside(g, hit->point + 1e-6 * hit->normal));
        CHECK(inside(g, hit->point - 1e-6 * hit->normal));
    }
    CHECK(checked > 100);
}

TEST_CASE("sor: aimed rays, bounds and extreme rays at every scale", "[geometry][sor]") {
    Random random(13);
    for (const double scale : {1e-2, 1.0, 1e3}) {
        auto points = vase();
        for (auto& q : points) q *= scale;
        const SorGeometry g = make_sor(points, true);
        const double size = 2.5 * scale;
        auto sample = [&](Random& r) {
            SurfaceSample q;
            const double y = r.uniform(g.height1, g.height2), angle = r.uniform(0.0, 2.0 * kPi);
            const auto& s = g.segments[static_cast<std::size_t>(segment_of(g, y))];
            const double rr = std::sqrt(std::max(s.r2(y), 0.0));
            q.point = {rr * std::cos(angle), y, rr * std::sin(angle)};
            q.normal = glm::normalize(glm::dvec3(q.point.x, -0.5 * s.r2_slope(y), q.point.z));
            q.curvature_radius = 0.05 * scale;
            q.edge_distance = std::min(y - g.height1, g.height2 - y);
            return q;
        };
        auto residual = [&](const glm::dvec3& p) { return surface_residual(g, p); };
        INFO("scale " << scale);
        const AimStats near =
            aim_at_surface(g, sample, residual, size, 2.0 * size, false, 200, random);
        const AimStats far =
            aim_at_surface(g, sample, residual, size, 1e6 * size, false, 200, random);
        CHECK(near.max_residual < 1e-10);
        CHECK(far.max_residual < 1e-8);
        report("sor near", near);
        report("sor far", far);
        boxes_around_surface(g, sample, size, 200, random);
        const Box3 b = object_bounds(g);
        for (int i = 0; i < 500; ++i)
            REQUIRE(hexant::runtime::geometry::contains(
                hexant::runtime::geometry::widened(b, 1e-15 * size), sample(random).point));
        random_rays_are_finite(g, size, glm::dvec3(0, scale, 0), 400, random);
    }
}
