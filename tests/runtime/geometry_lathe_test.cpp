// Static ray/lathe geometry for every spline type: the segments' polynomials
// against POV-Ray's interpolation rules, hits on a lathe that is a closed
// cylinder (analytic), first hits of random rays against an independent
// reference (the profile cut into thousands of straight pieces, each a cone
// frustum solved in long double), normals against finite differences of
// the revolved surface and outward by inside(), inside() against the
// crossing parity of the refined profile, rays aimed at sampled surface
// points at every scale, bounds around sampled points, and no NaN for
// extreme rays.
#include <vector>

#include "geometry_test_support.hpp"
#include "runtime/geometry/box_queries.hpp"
#include "runtime/objects/lathe/lathe_geometry.hpp"

using namespace geometry_test;
using hexant::runtime::geometry::LatheGeometry;
using hexant::runtime::geometry::LatheSpline;
using hexant::runtime::geometry::make_lathe;

namespace {

// A closed vase-like profile per spline type, its radius >= 0 along every
// segment (where a segment's radius goes negative, POV-Ray draws |r| but its
// inside rule ignores that part: see lathe_geometry.hpp).
std::vector<glm::dvec2> profile(LatheSpline spline) {
    switch (spline) {
        case LatheSpline::linear:
            return {{0.0, 0.0}, {1.0, 0.0}, {1.4, 0.8}, {0.6, 1.5}, {0.9, 2.2}, {0.0, 2.2}};
        case LatheSpline::quadratic:
            return {{0.0, -0.5}, {0.0, 0.0}, {1.0, 0.2}, {1.3, 1.0},
                    {0.9, 1.4},  {0.5, 1.9}, {0.0, 2.1}};
        case LatheSpline::cubic:
            return {{0.0, -0.5}, {0.0, 0.0}, {1.0, 0.1}, {1.2, 1.0},
                    {0.4, 1.6},  {0.8, 2.1}, {0.0, 2.3}, {0.0, 3.0}};
        case LatheSpline::bezier:
            return {{0.0, 0.0}, {0.8, 0.0}, {1.4, 0.4}, {1.2, 1.0}, {1.2, 1.0}, {1.0, 1.6},
                    {0.3, 1.4}, {0.6, 2.0}, {0.6, 2.0}, {0.4, 2.3}, {0.2, 2.2}, {0.0, 2.2}};
    }
    return {};
}

constexpr LatheSpline kSplines[] = {LatheSpline::linear, LatheSpline::quadratic, LatheSpline::cubic,
                                    LatheSpline::bezier};

// The profile refined into straight pieces in long double (r, y).
struct Piece {
    long double r0, y0, r1, y1;
};

std::vector<Piece> refine(const LatheGeometry& g, int per_segment) {
    std::vector<Piece> out;
    for (const auto& s : g.segments) {
        auto at = [&](long double t) {
            const long double r = ((s.a.x * t + s.b.x) * t + s.c.x) * t + s.d.x;
            const long double y = ((s.a.y * t + s.b.y) * t + s.c.y) * t + s.d.y;
            return std::pair<long double, long double>(std::fabs(r), y);
        };
        for (int i = 0; i < per_segment; ++i) {
            const auto [r0, y0] = at((long double)i / per_segment);
            const auto [r1, y1] = at((long double)(i + 1) / per_segment);
            out.push_back({r0, y0, r1, y1});
        }
    }
    return out;
}

// The nearest k > k_min where the ray meets the refined surface (each piece
// a frustum: rho(k) = r0 + (y(k) - y0)/(y1 - y0) (r1 - r0), squared).
std::optional<long double> reference_hit(const std::vector<Piece>& pieces, glm::dvec3 o,
                                         glm::dvec3 u, long double k_min) {
    const long double ox = o.x, oy = o.y, oz = o.z, ux = u.x, uy = u.y, uz = u.z;
    std::optional<long double> best;
    auto consider = [&](long double k, const Piece& p) {
        if (!(k > k_min) || (best && k >= *best)) return;
        const long double y = oy + k * uy;
        const long double rho =
            std::sqrt((ox + k * ux) * (ox + k * ux) + (oz + k * uz) * (oz + k * uz));
        if (p.y1 != p.y0) {
            const long double s = (y - p.y0) / (p.y1 - p.y0);
            if (s < 0 || s > 1) return;
        } else {
            const long double lo = std::min(p.r0, p.r1), hi = std::max(p.r0, p.r1);
            if (rho < lo || rho > hi) return;
        }
        best = k;
    };
    for (const Piece& p : pieces) {
        if (p.y1 == p.y0) {
            if (uy != 0) consider((p.y0 - oy) / uy, p);
            continue;
        }
        // rho(k) = alpha + beta k with alpha, beta from the frustum's line.
        const long double slope = (p.r1 - p.r0) / (p.y1 - p.y0);
        const long double alpha = p.r0 + (oy - p.y0) * slope, beta = uy * slope;
        // (ox + k ux)^2 + (oz + k uz)^2 = (alpha + beta k)^2
        const long double A = ux * ux + uz * uz - beta * beta;
        const long double B = 2 * (ox * ux + oz * uz - alpha * beta);
        const long double C = ox * ox + oz * oz - alpha * alpha;
        auto check = [&](long double k) {
            if (alpha + beta * k >= 0) consider(k, p);
        };
        if (std::fabs(A) < 1e-30L) {
            if (B != 0) check(-C / B);
            continue;
        }
        const long double disc = B * B - 4 * A * C;
        if (disc < 0) continue;
        const long double sq = std::sqrt(disc);
        check((-B - sq) / (2 * A));
        check((-B + sq) / (2 * A));
    }
    return best;
}

// Parity of the refined profile's crossings to the right (POV-Ray's rule).
bool reference_inside(const std::vector<Piece>& pieces, glm::dvec3 p) {
    const long double r = std::hypot((long double)p.x, (long double)p.z), y = p.y;
    int n = 0;
    for (const Piece& q : pieces) {
        if ((q.y0 <= y) == (q.y1 <= y)) continue;
        const long double s = (y - q.y0) / (q.y1 - q.y0);
        if (q.r0 + s * (q.r1 - q.r0) >= r) ++n;
    }
    return n % 2 == 1;
}

glm::dvec3 revolve(glm::dvec2 q, double angle) {
    return {std::fabs(q.x) * std::cos(angle), q.y, std::fabs(q.x) * std::sin(angle)};
}

// The distance of p from the surface, from its nearest profile point.
double surface_distance(const LatheGeometry& g, glm::dvec3 p) {
    const glm::dvec2 target(std::hypot(p.x, p.z), p.y);
    double best = kInf;
    for (const auto& s : g.segments) {
        auto dist = [&](double t) {
            const glm::dvec2 q = s.at(t);
            return glm::length(glm::dvec2(std::fabs(q.x), q.y) - target);
        };
        double bt = 0.0, bd = kInf;
        for (int i = 0; i <= 400; ++i) {
            const double d = dist(i / 400.0);
            if (d < bd) bd = d, bt = i / 400.0;
        }
        double lo = std::max(0.0, bt - 1.0 / 400), hi = std::min(1.0, bt + 1.0 / 400);
        for (int i = 0; i < 200; ++i) {
            const double a = lo + (hi - lo) / 3, b = hi - (hi - lo) / 3;
            if (dist(a) < dist(b))
                hi = b;
            else
                lo = a;
        }
        best = std::min({best, bd, dist(0.5 * (lo + hi))});
    }
    return best;
}

}  // namespace

TEST_CASE("lathe: segments follow POV-Ray's interpolation", "[geometry][lathe]") {
    using hexant::runtime::geometry::lathe_segment_count;
    CHECK(lathe_segment_count(LatheSpline::linear, 6) == 5);
    CHECK(lathe_segment_count(LatheSpline::quadratic, 6) == 4);
    CHECK(lathe_segment_count(LatheSpline::cubic, 6) == 3);
    CHECK(lathe_segment_count(LatheSpline::bezier, 8) == 2);
    CHECK(lathe_segment_count(LatheSpline::cubic, 3) == 0);
    for (const LatheSpline spline : kSplines) {
        const auto points = profile(spline);
        const LatheGeometry g = make_lathe(spline, points);
        REQUIRE(g.segments.size() ==
                static_cast<std::size_t>(lathe_segment_count(spline, points.size())));
        for (std::size_t i = 0; i < g.segments.size(); ++i) {
            const auto& s = g.segments[i];
            glm::dvec2 start(0.0), end(0.0);
            switch (spline) {
                case LatheSpline::linear:
                    start = points[i];
                    end = points[i + 1];
                    break;
                case LatheSpline::quadratic:
                case LatheSpline::cubic:
                    start = points[i + 1];
                    end = points[i + 2];
                    break;
                case LatheSpline::bezier:
                    start = points[4 * i];
                    end = points[4 * i + 3];
                    break;
            }
            CHECK(glm::length(s.at(0.0) - start) < 1e-15);
            CHECK(glm::length(s.at(1.0) - end) < 1e-14);
            if (spline == LatheSpline::cubic) {  // Catmull-Rom tangents
                CHECK(glm::length(s.slope(0.0) - 0.5 * (points[i + 2] - points[i])) < 1e-14);
                CHECK(glm::length(s.slope(1.0) - 0.5 * (points[i + 3] - points[i + 1])) < 1e-14);
            }
            if (spline == LatheSpline::quadratic)  // POV-Ray's: slope (P2 - P0)/2 at the start
                CHECK(glm::length(s.slope(0.0) - 0.5 * (points[i + 2] - points[i])) < 1e-14);
            if (spline == LatheSpline::bezier)
                CHECK(glm::length(s.slope(0.0) - 3.0 * (points[4 * i + 1] - points[4 * i])) <
                      1e-14);
        }
    }
}

TEST_CASE("lathe: a closed cylinder made as a linear lathe", "[geometry][lathe]") {
    const LatheGeometry g =
        make_lathe(LatheSpline::linear, {{0.0, 0.0}, {1.0, 0.0}, {1.0, 2.0}, {0.0, 2.0}});
    // Side, from outside along -x.
    auto hit = intersect(g, Ray3{{5.0, 1.0, 0.0}, {-1.0, 0.0, 0.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == Approx(4.0).epsilon(1e-14));
    CHECK(hit->normal.x == Approx(1.0));
    CHECK(hit->part == 1);
    CHECK(hit->uv.y == Approx((1.0 + 0.5) / 3.0));
    // Top cap from above (normal +y), bottom from below (-y), off the axis.
    hit = intersect(g, Ray3{{0.3, 5.0, 0.2}, {0.0, -2.0, 0.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == Approx(1.5).epsilon(1e-14));
    CHECK(hit->normal.y == Approx(1.0));
    hit = intersect(g, Ray3{{0.3, -5.0, 0.2}, {0.0, 1.0, 0.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == Approx(5.0).epsilon(1e-14));
    CHECK(hit->normal.y == Approx(-1.0));
    // Along the axis (POV-Ray's pole), and from inside (the far wall, outward).
    hit = intersect(g, Ray3{{0.0, 5.0, 0.0}, {0.0, -1.0, 0.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == Approx(3.0));
    hit = intersect(g, Ray3{{0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == Approx(1.0).epsilon(1e-14));
    CHECK(hit->normal.z == Approx(1.0));
    // Horizontal rays exactly at and near a cap's height; misses.
    CHECK(!intersect(g, Ray3{{5.0, 3.0, 0.0}, {-1.0, 0.0, 0.0}}, 0.0, kInf));
    CHECK(!intersect(g, Ray3{{5.0, 1.0, 1.5}, {-1.0, 0.0, 0.0}}, 0.0, kInf));
    hit = intersect(g, Ray3{{5.0, 1.0 + 1e-12, 0.5}, {-1.0, 1e-15, 0.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == Approx(5.0 - std::sqrt(0.75)).epsilon(1e-14));
    CHECK(inside(g, {0.5, 1.0, 0.5}));
    CHECK(!inside(g, {1.5, 1.0, 0.0}));
    CHECK(!inside(g, {0.5, 2.5, 0.0}));
}

TEST_CASE("lathe: first hits against the refined profile", "[geometry][lathe]") {
    Random random(2024);
    for (const LatheSpline spline : kSplines) {
        const LatheGeometry g = make_lathe(spline, profile(spline));
        const auto pieces = refine(g, 3000);
        int hits = 0, compared = 0;
        for (int i = 0; i < 600; ++i) {
            const glm::dvec3 target = {random.uniform(-1.3, 1.3), random.uniform(-0.2, 2.6),
                                       random.uniform(-1.3, 1.3)};
            glm::dvec3 origin = target + random.uniform(2.0, 6.0) * random.unit_vector();
            if (i % 4 == 0) origin.y = target.y + random.uniform(-1e-6, 1e-6);  // nearly horizontal
            const glm::dvec3 dir = glm::normalize(target - origin);
            const auto ours = intersect(g, Ray3{origin, dir}, 0.0, kInf);
            const auto ref = reference_hit(pieces, origin, dir, 0.0L);
            INFO("spline " << static_cast<int>(spline) << " ray " << i);
            if (ours && ref) {
                ++compared;
                // Agreement to the refinement's chord error, unless the ray
                // grazes (then the nearest hit may flip between close ones).
                const double cosine = std::fabs(glm::dot(ours->normal, dir));
                if (cosine > 0.05) CHECK(std::fabs(ours->s - (double)*ref) < 1e-5);
            } else if (ours) {
                CHECK(std::fabs(glm::dot(ours->normal, dir)) < 0.05);
            } else if (ref) {
                // A miss only where the refined surface is met at a graze.
                const glm::dvec3 p = origin + (double)*ref * dir;
                CHECK(surface_distance(g, p) < 1e-5);
                const auto near = intersect(g, Ray3{origin, dir}, 0.0, kInf);
                CHECK(!near);
            }
            if (ours) {
                ++hits;
                REQUIRE(well_formed(*ours));
                CHECK(surface_distance(g, ours->point) < 1e-12);
            }
        }
        CHECK(hits > 200);
        CHECK(compared > 200);
    }
}

TEST_CASE("lathe: normals against finite differences, outward", "[geometry][lathe]") {
    Random random(77);
    for (const LatheSpline spline : kSplines) {
        const LatheGeometry g = make_lathe(spline, profile(spline));
        int checked = 0;
        for (int i = 0; i < 400; ++i) {
            const std::size_t j =
                static_cast<std::size_t>(random.integer(0, (int)g.segments.size() - 1));
            const double t = random.uniform(0.02, 0.98), angle = random.uniform(0.0, 2.0 * kPi);
            const auto& s = g.segments[j];
            if (std::fabs(s.at(t).x) < 0.05) continue;  // near the axis
            const glm::dvec3 p = revolve(s.at(t), angle);
            const double h = 1e-6;
            const glm::dvec3 along = revolve(s.at(t + h), angle) - revolve(s.at(t - h), angle);
            const glm::dvec3 around = revolve(s.at(t), angle + h) - revolve(s.at(t), angle - h);
            glm::dvec3 expected = glm::cross(along, around);
            if (glm::length(expected) < 1e-14) continue;
            expected = glm::normalize(expected);
            // A ray at the point along -expected (from outside or inside).
            const glm::dvec3 origin = p + 0.5 * expected;
            const auto hit = intersect(g, Ray3{origin, -expected}, 0.0, kInf);
            if (!hit || std::fabs(hit->s - 0.5) > 1e-9) continue;  // another sheet in front
            ++checked;
            INFO("spline " << static_cast<int>(spline) << " segment " << j << " t " << t);
            CHECK(std::fabs(std::fabs(glm::dot(hit->normal, expected)) - 1.0) < 1e-8);
            // Outward: just outside along the normal is outside, just inside inside.
            CHECK(!inside(g, hit->point + 1e-6 * hit->normal));
            CHECK(inside(g, hit->point - 1e-6 * hit->normal));
        }
        CHECK(checked > 100);
    }
}

TEST_CASE("lathe: inside against the refined profile's parity", "[geometry][lathe]") {
    Random random(5);
    for (const LatheSpline spline : kSplines) {
        const LatheGeometry g = make_lathe(spline, profile(spline));
        const auto pieces = refine(g, 3000);
        int in = 0;
        for (int i = 0; i < 3000; ++i) {
            const glm::dvec3 p{random.uniform(-1.6, 1.6), random.uniform(-0.3, 2.7),
                               random.uniform(-1.6, 1.6)};
            if (surface_distance(g, p) < 1e-5) continue;
            INFO("point " << p.x << " " << p.y << " " << p.z);
            CHECK(inside(g, p) == reference_inside(pieces, p));
            in += inside(g, p);
        }
        CHECK(in > 300);
    }
}

TEST_CASE("lathe: aimed rays, bounds and extreme rays at every scale", "[geometry][lathe]") {
    Random random(99);
    for (const LatheSpline spline : kSplines) {
        for (const double scale : {1e-6, 1.0, 1e6}) {
            for (const glm::dvec3 offset : {glm::dvec3(0.0), glm::dvec3(0.0, 3e5, 0.0)}) {
                auto points = profile(spline);
                for (auto& q : points) q = q * scale + glm::dvec2(0.0, offset.y * scale);
                const LatheGeometry g = make_lathe(spline, points);
                const double size = 3.0 * scale;
                auto sample = [&](Random& r) {
                    SurfaceSample q;
                    const auto& s = g.segments[static_cast<std::size_t>(
                        r.integer(0, (int)g.segments.size() - 1))];
                    const double t = r.uniform(0.0, 1.0), angle = r.uniform(0.0, 2.0 * kPi);
                    q.point = revolve(s.at(t), angle);
                    const double h = 1e-7;
                    const glm::dvec3 along = revolve(s.at(std::min(t + h, 1.0)), angle) -
                                             revolve(s.at(std::max(t - h, 0.0)), angle);
                    const glm::dvec3 around =
                        revolve(s.at(t), angle + h) - revolve(s.at(t), angle - h);
                    const glm::dvec3 n = glm::cross(along, around);
                    q.normal = glm::length(n) > 0.0 ? glm::normalize(n) : glm::dvec3(0, 1, 0);
                    if (!inside(g, q.point - 1e-7 * size * q.normal)) q.normal = -q.normal;
                    // Curvature is bounded by the profile's; joints are edges.
                    q.curvature_radius = 0.05 * scale;
                    q.edge_distance = std::min(t, 1.0 - t) * 0.1 * scale;
                    return q;
                };
                auto residual = [&](const glm::dvec3& p) { return surface_distance(g, p); };
                INFO("spline " << static_cast<int>(spline) << " scale " << scale);
                const AimStats near =
                    aim_at_surface(g, sample, residual, size, 2.0 * size, false, 150, random);
                const AimStats far =
                    aim_at_surface(g, sample, residual, size, 1e6 * size, false, 150, random);
                CHECK(near.max_residual < 1e-11);
                CHECK(far.max_residual < 1e-9);
                report("lathe near", near);
                report("lathe far", far);
                boxes_around_surface(g, sample, size, 200, random);
                const Box3 b = object_bounds(g);
                for (int i = 0; i < 500; ++i) {
                    const glm::dvec3 p = sample(random).point;
                    REQUIRE(hexant::runtime::geometry::contains(
                        hexant::runtime::geometry::widened(b, 1e-15 * size), p));
                }
                random_rays_are_finite(g, size, offset * scale + glm::dvec3(0, scale, 0), 400,
                                       random);
            }
        }
    }
}

TEST_CASE("lathe: degenerate inputs are empty, never NaN", "[geometry][lathe]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK(make_lathe(LatheSpline::linear, {{1.0, 0.0}}).segments.empty());
    CHECK(make_lathe(LatheSpline::cubic, {{1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}}).segments.empty());
    CHECK(make_lathe(LatheSpline::linear, {{1.0, 0.0}, {nan, 1.0}}).segments.empty());
    const LatheGeometry point = make_lathe(LatheSpline::linear, {{0.0, 0.0}, {0.0, 0.0}});
    CHECK(!intersect(point, Ray3{{1.0, 0.0, 0.0}, {-1.0, 0.0, 0.0}}, 0.0, kInf));
    // A flat disc (a profile along y = 0): hits from above, none sideways.
    const LatheGeometry disc = make_lathe(LatheSpline::linear, {{0.0, 0.0}, {1.0, 0.0}});
    const auto hit = intersect(disc, Ray3{{0.2, 1.0, 0.1}, {0.0, -1.0, 0.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == Approx(1.0));
    CHECK(!intersect(disc, Ray3{{5.0, 0.0, 0.0}, {-1.0, 0.0, 0.0}}, 0.0, kInf));
}
