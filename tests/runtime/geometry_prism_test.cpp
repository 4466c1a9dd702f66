// Static ray/prism geometry (linear_sweep, linear_spline): analytic hits on
// caps and sides, holes and concave outlines by the even-odd rule, outward
// side normals, open prisms, seams between side faces, rays aimed at
// sampled surface points at every scale, inside() against an independent
// test and the ray parity, and surface_may_meet around surface points.
#include <vector>

#include "geometry_test_support.hpp"
#include "runtime/objects/prism/prism_geometry.hpp"

using namespace geometry_test;
using hexant::runtime::geometry::PrismGeometry;

namespace {

using Outlines = std::vector<std::vector<glm::dvec2>>;

bool inside_by_angles(const Outlines& outlines, glm::dvec2 p) {
    int parity = 0;
    for (const auto& outline : outlines) {
        double total = 0.0;
        for (std::size_t i = 0; i < outline.size(); ++i) {
            const glm::dvec2 a = outline[i] - p, b = outline[(i + 1) % outline.size()] - p;
            total += std::atan2(a.x * b.y - a.y * b.x, a.x * b.x + a.y * b.y);
        }
        parity += static_cast<int>(std::lround(std::fabs(total) / (2.0 * kPi)));
    }
    return parity % 2 == 1;
}

double distance_2d(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) {
    const glm::dvec2 e = b - a;
    const double t = std::clamp(glm::dot(p - a, e) / glm::dot(e, e), 0.0, 1.0);
    return glm::length(a + t * e - p);
}

// A ring (square with a square hole) and a concave star, in x-z.
Outlines test_outlines(double scale, glm::dvec2 offset) {
    Outlines outlines = {
        {{0.0, 0.0}, {4.0, 0.0}, {4.0, 4.0}, {0.0, 4.0}},
        {{1.0, 1.0}, {1.0, 3.0}, {3.0, 3.0}, {3.0, 1.0}},
    };
    std::vector<glm::dvec2> star;
    for (int i = 0; i < 10; ++i) {
        const double a = 2.0 * kPi * i / 10.0, radius = i % 2 == 0 ? 1.8 : 0.7;
        star.push_back({7.0 + radius * std::cos(a), 2.0 + radius * std::sin(a)});
    }
    outlines.push_back(star);
    for (auto& outline : outlines) {
        for (auto& q : outline) q = offset + scale * q;
    }
    return outlines;
}

PrismGeometry make_prism(const Outlines& outlines, double h1, double h2, bool open) {
    PrismGeometry g;
    g.height1 = h1;
    g.height2 = h2;
    g.open = open;
    for (const auto& outline : outlines) {
        g.points.insert(g.points.end(), outline.begin(), outline.end());
        g.points.push_back(outline.front());
    }
    return g;
}

struct PrismCase {
    Outlines outlines;
    PrismGeometry g;
    double y0, y1, scale;

    SurfaceSample sample(Random& random) const {
        const bool cap = !g.open && random.uniform() < 0.4;
        if (cap) {
            for (;;) {
                const glm::dvec2 lo = outlines[0][0],
                                 hi = outlines[2][0] + glm::dvec2(0.0, 2.0 * scale);
                const glm::dvec2 q{random.uniform(lo.x, hi.x + 0.2 * scale),
                                   random.uniform(lo.y, lo.y + 4.0 * scale)};
                if (!inside_by_angles(outlines, q)) continue;
                const double edge = edge_distance(q);
                if (edge < 1e-4 * scale) continue;
                const bool top = random.uniform() < 0.5;
                SurfaceSample s{{q.x, top ? y1 : y0, q.y}, {0.0, top ? 1.0 : -1.0, 0.0}};
                s.edge_distance = edge;
                return s;
            }
        }
        const auto& outline = outlines[random.integer(0, (int)outlines.size() - 1)];
        const std::size_t i = random.integer(0, (int)outline.size() - 1);
        const glm::dvec2 a = outline[i], b = outline[(i + 1) % outline.size()];
        const double lambda = random.uniform(1e-3, 1.0 - 1e-3);
        const double y = y0 + (y1 - y0) * random.uniform(1e-3, 1.0 - 1e-3);
        const glm::dvec2 q = a + lambda * (b - a);
        glm::dvec2 right{b.y - a.y, a.x - b.x};
        right /= glm::length(right);
        // Outward: the side where the independent test says "outside".
        const bool right_inside = inside_by_angles(outlines, q + 1e-6 * scale * right);
        const glm::dvec2 out = right_inside ? -right : right;
        SurfaceSample s{{q.x, y, q.y}, {out.x, 0.0, out.y}};
        s.edge_distance = std::min(
            {lambda * glm::length(b - a), (1.0 - lambda) * glm::length(b - a), y - y0, y1 - y});
        return s;
    }

    double edge_distance(glm::dvec2 q) const {
        double d = kInf;
        for (const auto& outline : outlines) {
            for (std::size_t i = 0; i < outline.size(); ++i) {
                d = std::min(d, distance_2d(outline[i], outline[(i + 1) % outline.size()], q));
            }
        }
        return d;
    }

    // The distance to the nearest side face or cap, for points near the surface.
    double residual(const glm::dvec3& p) const {
        const glm::dvec2 q{p.x, p.z};
        const double y_out = std::max({y0 - p.y, p.y - y1, 0.0});
        double d = kInf;
        for (const auto& outline : outlines) {
            for (std::size_t i = 0; i < outline.size(); ++i) {
                const double e = distance_2d(outline[i], outline[(i + 1) % outline.size()], q);
                d = std::min(d, std::sqrt(e * e + y_out * y_out));
            }
        }
        if (!g.open && inside_by_angles(outlines, q)) {
            d = std::min({d, std::fabs(p.y - y0), std::fabs(p.y - y1)});
        }
        return d;
    }
};

template <class G>
int crossings(const G& g, const glm::dvec3& p, const glm::dvec3& dir) {
    int count = 0;
    double s = 0.0;
    while (auto hit = intersect(g, Ray3{p, dir}, s, kInf)) {
        s = hit->s;
        if (++count > 64) break;
    }
    return count;
}

}  // namespace

TEST_CASE("prism: analytic hits, caps, holes, outward normals", "[runtime][geometry]") {
    const PrismGeometry square = make_prism({{{0, 0}, {2, 0}, {2, 2}, {0, 2}}}, 1.0, 0.0, false);
    auto hit = intersect(square, Ray3{{-5.0, 0.5, 1.0}, {1.0, 0.0, 0.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == 5.0);
    CHECK(hit->part == 2 + 3);  // the edge from (0, 2) back to (0, 0)
    CHECK(hit->normal == glm::dvec3(-1.0, 0.0, 0.0));
    CHECK(hit->uv.x == Approx(0.5));
    CHECK(hit->uv.y == Approx(0.5));
    hit = intersect(square, Ray3{{1.0, 5.0, 1.5}, {0.0, -2.0, 0.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == 2.0);
    CHECK(hit->part == 1);
    CHECK(hit->normal == glm::dvec3(0.0, 1.0, 0.0));
    CHECK(hit->uv == glm::dvec2(1.0, 1.5));
    hit = intersect(square, Ray3{{1.0, 0.5, 1.0}, {0.0, -1.0, 0.0}}, 0.0, kInf);  // from inside
    REQUIRE(hit);
    CHECK(hit->part == 0);
    CHECK(hit->normal == glm::dvec3(0.0, -1.0, 0.0));
    CHECK(hit->s == 0.5);
    // Clockwise outline: normals still outward.
    const PrismGeometry clockwise = make_prism({{{0, 0}, {0, 2}, {2, 2}, {2, 0}}}, 0.0, 1.0, false);
    hit = intersect(clockwise, Ray3{{5.0, 0.5, 1.0}, {-1.0, 0.0, 0.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->normal == glm::dvec3(1.0, 0.0, 0.0));
    // A ring: the hole's walls face into the hole; a vertical ray down the hole misses.
    const Outlines ring = {{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{1, 1}, {3, 1}, {3, 3}, {1, 3}}};
    const PrismGeometry g = make_prism(ring, 0.0, 1.0, false);
    CHECK_FALSE(intersect(g, Ray3{{2.0, 5.0, 2.0}, {0.0, -1.0, 0.0}}, -kInf, kInf));
    hit = intersect(g, Ray3{{2.0, 0.5, 2.0}, {1.0, 0.0, 0.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == 1.0);
    CHECK(hit->normal == glm::dvec3(-1.0, 0.0, 0.0));
    CHECK(inside(g, {0.5, 0.5, 0.5}));
    CHECK_FALSE(inside(g, {2.0, 0.5, 2.0}));
    CHECK_FALSE(inside(g, {0.5, 1.5, 0.5}));
    // Open: no caps.
    const PrismGeometry open = make_prism(ring, 0.0, 1.0, true);
    CHECK_FALSE(intersect(open, Ray3{{0.5, 5.0, 0.5}, {0.0, -1.0, 0.0}}, -kInf, kInf));
    CHECK(inside(open, {0.5, 0.5, 0.5}));
    // The last outline left open is closed.
    PrismGeometry unclosed = g;
    unclosed.points.pop_back();
    CHECK_FALSE(intersect(unclosed, Ray3{{2.0, 5.0, 2.0}, {0.0, -1.0, 0.0}}, -kInf, kInf));
    CHECK(intersect(unclosed, Ray3{{0.5, 5.0, 0.5}, {0.0, -1.0, 0.0}}, 0.0, kInf));
    const Box3 b = object_bounds(g);
    CHECK(b.lo == glm::dvec3(0.0, 0.0, 0.0));
    CHECK(b.hi == glm::dvec3(4.0, 1.0, 4.0));
}

TEST_CASE("prism: rays through the seams between side faces", "[runtime][geometry]") {
    const Outlines outlines = test_outlines(1.0, {0.1, -0.2});
    const PrismGeometry g = make_prism(outlines, -0.5, 0.5, false);
    Random random(61);
    int leaks = 0, tested = 0;
    for (int i = 0; i < 6000; ++i) {
        const auto& outline = outlines[random.integer(0, 2)];
        const glm::dvec2 corner = outline[random.integer(0, (int)outline.size() - 1)];
        const glm::dvec3 target{corner.x, random.uniform(-0.45, 0.45), corner.y};
        // Only rays that pass from outside into the solid through the
        // corner's vertical edge: lines that merely touch a convex corner
        // may honestly miss by the rounding of their direction.
        const glm::dvec3 away = random.unit_vector();
        const glm::dvec2 step{1e-3 * away.x, 1e-3 * away.z};
        if (inside_by_angles(outlines, corner + step) ||
            !inside_by_angles(outlines, corner - step)) {
            continue;
        }
        ++tested;
        const glm::dvec3 from = target + random.log_uniform(0.1, 1e6) * away;
        if (!intersect(g, Ray3{from, target - from}, 0.0, kInf)) ++leaks;
    }
    CHECK(tested > 500);
    CHECK(leaks == 0);
}

TEST_CASE("prism: aimed rays at every scale, inside, parity, may-meet", "[runtime][geometry]") {
    Random random(62);
    struct Case {
        const char* name;
        double scale;
        glm::dvec2 offset;
        double y_base, distance;
        bool open;
    };
    const Case cases[] = {
        {"prism 1 near", 1.0, {0.0, 0.0}, 0.0, 10.0, false},
        {"prism 1 from 1e6", 1.0, {0.0, 0.0}, 0.0, 1e6, false},
        {"prism 1e-6 from 1e6", 1e-6, {0.3, -0.1}, 0.2, 1e6, false},
        {"prism 1e6 at 1e6 from 1e6", 1e6, {1e6, -1e6}, 2e6, 1e6, false},
        {"prism open", 1.0, {0.0, 0.0}, 0.0, 10.0, true},
    };
    for (const Case& c : cases) {
        INFO(c.name);
        const Outlines outlines = test_outlines(c.scale, c.offset);
        const double y0 = c.y_base, y1 = c.y_base + 1.5 * c.scale;
        const PrismCase pc{outlines, make_prism(outlines, y1, y0, c.open), y0, y1, c.scale};
        const AimStats stats = aim_at_surface(
            pc.g, [&](Random& r) { return pc.sample(r); },
            [&](const glm::dvec3& p) { return pc.residual(p); }, c.scale, c.distance, false, 2000,
            random);
        report(c.name, stats);
        CHECK(stats.grazing_misses <= stats.rays / 50);
        CHECK(stats.max_residual < 16.0 * kEps);
        CHECK(stats.max_point_mismatch < 16.0 * kEps);
        const glm::dvec3 mid{c.offset.x + 4.5 * c.scale, 0.5 * (y0 + y1),
                             c.offset.y + 2.0 * c.scale};
        CHECK(random_rays_are_finite(pc.g, 5.0 * c.scale, mid, 2000, random) > 20);
        boxes_around_surface(
            pc.g, [&](Random& r) { return pc.sample(r); }, c.scale, 10000, random);
        for (int i = 0; i < 1500; ++i) {
            const glm::dvec3 p =
                mid + c.scale * glm::dvec3(random.uniform(-5.5, 5.5), random.uniform(-1.0, 1.0),
                                           random.uniform(-2.5, 2.5));
            if (pc.residual(p) < 1e-6 * c.scale) continue;
            const bool expected = p.y >= y0 && p.y <= y1 && inside_by_angles(outlines, {p.x, p.z});
            CHECK(inside(pc.g, p) == expected);
            if (!c.open) CHECK(expected == (crossings(pc.g, p, random.unit_vector()) % 2 == 1));
        }
        // No: in the ring's hole, inside the solid, above the star.
        const glm::dvec3 hole{c.offset.x + 2.0 * c.scale, mid.y, c.offset.y + 2.0 * c.scale};
        CHECK_FALSE(surface_may_meet(pc.g, Box3{hole - 0.3 * c.scale, hole + 0.3 * c.scale}));
        const glm::dvec3 solid{c.offset.x + 0.5 * c.scale, mid.y, c.offset.y + 0.5 * c.scale};
        CHECK_FALSE(surface_may_meet(pc.g, Box3{solid - 0.2 * c.scale, solid + 0.2 * c.scale}));
        const glm::dvec3 above{c.offset.x + 7.0 * c.scale, y1 + c.scale,
                               c.offset.y + 2.0 * c.scale};
        CHECK_FALSE(surface_may_meet(pc.g, Box3{above - 0.2 * c.scale, above + 0.2 * c.scale}));
    }
}
