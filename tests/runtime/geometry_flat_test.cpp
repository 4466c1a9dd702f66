// Static ray/triangle, ray/smooth_triangle and ray/polygon geometry:
// analytic hits, watertightness (rays through the shared edges and vertices
// of a closed mesh always hit it), rays aimed at sampled interior points at
// every scale, POV-Ray's polygon outlines (holes, unclosed last outline,
// even-odd), and surface_may_meet around surface points.
#include <array>
#include <vector>

#include "geometry_test_support.hpp"
#include "runtime/objects/polygon/polygon_geometry.hpp"
#include "runtime/objects/triangle/smooth_triangle_geometry.hpp"
#include "runtime/objects/triangle/triangle_geometry.hpp"

using namespace geometry_test;
using hexant::runtime::geometry::PolygonGeometry;
using hexant::runtime::geometry::SmoothTriangleGeometry;
using hexant::runtime::geometry::TriangleGeometry;

namespace {

// The distance from p to the plane through a, b, c, in long double.
double plane_residual(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                      const glm::dvec3& p) {
    const long double ux = (long double)b.x - a.x, uy = (long double)b.y - a.y,
                      uz = (long double)b.z - a.z;
    const long double vx = (long double)c.x - a.x, vy = (long double)c.y - a.y,
                      vz = (long double)c.z - a.z;
    const long double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    const long double len = std::sqrt(nx * nx + ny * ny + nz * nz);
    const long double d = ((long double)p.x - a.x) * nx + ((long double)p.y - a.y) * ny +
                          ((long double)p.z - a.z) * nz;
    return static_cast<double>(std::fabs(d) / len);
}

double segment_distance(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& p) {
    const glm::dvec3 e = b - a;
    const double t = std::clamp(glm::dot(p - a, e) / glm::dot(e, e), 0.0, 1.0);
    return glm::length(a + t * e - p);
}

SurfaceSample sample_triangle(const TriangleGeometry& g, Random& random) {
    double u = random.uniform(), v = random.uniform();
    if (u + v > 1.0) {
        u = 1.0 - u;
        v = 1.0 - v;
    }
    SurfaceSample q;
    q.point = g.p1 + u * (g.p2 - g.p1) + v * (g.p3 - g.p1);
    q.normal = glm::normalize(glm::cross(g.p2 - g.p1, g.p3 - g.p1));
    q.edge_distance =
        std::min({segment_distance(g.p1, g.p2, q.point), segment_distance(g.p2, g.p3, q.point),
                  segment_distance(g.p3, g.p1, q.point)});
    return q;
}

// An independent even-odd test in 2D: the winding number's parity, from
// the signed angles the edges subtend (no crossing rule at all).
bool inside_by_angles(const std::vector<std::vector<glm::dvec2>>& outlines, glm::dvec2 p) {
    double total = 0.0;
    int parity = 0;
    for (const auto& outline : outlines) {
        total = 0.0;
        for (std::size_t i = 0; i < outline.size(); ++i) {
            const glm::dvec2 a = outline[i] - p, b = outline[(i + 1) % outline.size()] - p;
            total += std::atan2(a.x * b.y - a.y * b.x, a.x * b.x + a.y * b.y);
        }
        parity += static_cast<int>(std::lround(std::fabs(total) / (2.0 * kPi)));
    }
    return parity % 2 == 1;
}

// POV-Ray's point list for outlines: each closed by repeating its first point.
std::vector<glm::dvec2> pov_points(const std::vector<std::vector<glm::dvec2>>& outlines) {
    std::vector<glm::dvec2> points;
    for (const auto& outline : outlines) {
        points.insert(points.end(), outline.begin(), outline.end());
        points.push_back(outline.front());
    }
    return points;
}

// A square with a square hole and a concave star beside it.
std::vector<std::vector<glm::dvec2>> test_outlines() {
    std::vector<std::vector<glm::dvec2>> outlines = {
        {{0.0, 0.0}, {4.0, 0.0}, {4.0, 4.0}, {0.0, 4.0}},
        {{1.0, 1.0}, {1.0, 3.0}, {3.0, 3.0}, {3.0, 1.0}},  // the hole, opposite winding
    };
    std::vector<glm::dvec2> star;
    for (int i = 0; i < 10; ++i) {
        const double a = 2.0 * kPi * i / 10.0, radius = i % 2 == 0 ? 1.8 : 0.7;
        star.push_back({7.0 + radius * std::cos(a), 2.0 + radius * std::sin(a)});
    }
    outlines.push_back(star);
    return outlines;
}

// A plane frame for putting 2D outlines into space: origin, two axes, scale.
struct Placement {
    glm::dvec3 origin, e1, e2;
    double scale;
    glm::dvec3 at(glm::dvec2 q) const { return origin + scale * (q.x * e1 + q.y * e2); }
};

}  // namespace

TEST_CASE("triangle: analytic hits, edges, degenerate cases", "[runtime][geometry]") {
    const TriangleGeometry g{{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}};
    auto hit = intersect(g, Ray3{{0.25, 0.5, 5.0}, {0.0, 0.0, -1.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == 5.0);
    CHECK(hit->normal == glm::dvec3(0.0, 0.0, 1.0));
    CHECK(hit->uv.x == 0.25);
    CHECK(hit->uv.y == 0.5);
    CHECK(hit->point == glm::dvec3(0.25, 0.5, 0.0));
    hit = intersect(g, Ray3{{0.25, 0.5, -5.0}, {0.0, 0.0, 2.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == 2.5);
    CHECK(hit->normal == glm::dvec3(0.0, 0.0, 1.0));  // not flipped toward the ray
    CHECK(intersect(g, Ray3{{0.5, 0.0, 5.0}, {0.0, 0.0, -1.0}}, 0.0, kInf));  // on an edge
    CHECK(intersect(g, Ray3{{0.0, 0.0, 5.0}, {0.0, 0.0, -1.0}}, 0.0, kInf));  // a vertex
    CHECK_FALSE(intersect(g, Ray3{{0.6, 0.6, 5.0}, {0.0, 0.0, -1.0}}, 0.0, kInf));
    CHECK_FALSE(intersect(g, Ray3{{-5.0, 0.2, 0.0}, {1.0, 0.0, 0.0}}, -kInf, kInf));  // in plane
    CHECK_FALSE(intersect(TriangleGeometry{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}},
                          Ray3{{0, 1, 0}, {1, -1, 0}}, -kInf, kInf));
    CHECK_FALSE(inside(g, {0.2, 0.2, 0.0}));
    const Box3 b = object_bounds(g);
    CHECK(b.lo == glm::dvec3(0.0));
    CHECK(b.hi == glm::dvec3(1.0, 1.0, 0.0));
}

TEST_CASE("triangle: watertight on a closed mesh, at every scale", "[runtime][geometry]") {
    // A subdivided octahedron pushed onto a sphere: 512 triangles, every edge
    // shared by two. Rays from inside through vertices, edge points and at
    // random must leave through at least one triangle.
    std::vector<std::array<glm::dvec3, 3>> unit;
    const glm::dvec3 axes[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    for (int sx : {0, 1}) {
        for (int sy : {2, 3}) {
            for (int sz : {4, 5}) {
                unit.push_back({axes[sx], axes[sy], axes[sz]});
            }
        }
    }
    for (int level = 0; level < 3; ++level) {
        std::vector<std::array<glm::dvec3, 3>> finer;
        for (const auto& t : unit) {
            const glm::dvec3 a = glm::normalize(t[0] + t[1]), b = glm::normalize(t[1] + t[2]),
                             c = glm::normalize(t[2] + t[0]);
            finer.push_back({t[0], a, c});
            finer.push_back({a, t[1], b});
            finer.push_back({c, b, t[2]});
            finer.push_back({a, b, c});
        }
        unit = finer;
    }
    Random random(51);
    for (const auto& [scale, offset] :
         {std::pair{1.0, glm::dvec3(0.0)}, std::pair{1e-6, glm::dvec3(0.3, 0.1, -0.2)},
          std::pair{1e6, glm::dvec3(1e6, -2e6, 5e5)}, std::pair{1.0, glm::dvec3(1e6, 1e6, 1e6)}}) {
        std::vector<TriangleGeometry> mesh;
        for (const auto& t : unit) {
            mesh.push_back({offset + scale * t[0], offset + scale * t[1], offset + scale * t[2]});
        }
        auto hits_mesh = [&](const Ray3& ray) {
            for (const TriangleGeometry& t : mesh) {
                if (intersect(t, ray, 0.0, kInf)) return true;
            }
            return false;
        };
        int leaks = 0;
        for (int i = 0; i < 600; ++i) {
            const TriangleGeometry& t = mesh[random.integer(0, (int)mesh.size() - 1)];
            glm::dvec3 target;
            switch (i % 3) {
                case 0:
                    target = t.p1;
                    break;  // a vertex
                case 1:
                    target = t.p1 + random.uniform() * (t.p2 - t.p1);
                    break;  // an edge
                default:
                    target = sample_triangle(t, random).point;
            }
            const glm::dvec3 from = offset + 0.3 * scale * random.in_cube(1.0);
            if (!hits_mesh(Ray3{from, target - from})) ++leaks;
        }
        INFO("scale " << scale << " offset " << offset.x);
        CHECK(leaks == 0);
    }
}

TEST_CASE("triangle: aimed rays at every scale, may-meet", "[runtime][geometry]") {
    Random random(52);
    struct Case {
        const char* name;
        double scale;
        glm::dvec3 offset;
        double distance;
    };
    const Case cases[] = {
        {"triangle 1 near", 1.0, {0.0, 0.0, 0.0}, 3.0},
        {"triangle 1 from 1e6", 1.0, {0.0, 0.0, 0.0}, 1e6},
        {"triangle 1e-6 from 1e6", 1e-6, {0.3, 0.1, -0.2}, 1e6},
        {"triangle 1e6 at 1e6 from 1e6", 1e6, {1e6, -1e6, 2e6}, 1e6},
        {"triangle 1 at 1e6 from 10", 1.0, {1e6, -1e6, 2e6}, 10.0},
    };
    for (const Case& c : cases) {
        INFO(c.name);
        for (int shape = 0; shape < 5; ++shape) {
            const TriangleGeometry g{c.offset + c.scale * random.in_cube(1.0),
                                     c.offset + c.scale * random.in_cube(1.0),
                                     c.offset + c.scale * random.in_cube(1.0)};
            const AimStats stats = aim_at_surface(
                g, [&](Random& r) { return sample_triangle(g, r); },
                [&](const glm::dvec3& p) { return plane_residual(g.p1, g.p2, g.p3, p); }, c.scale,
                c.distance, true, 400, random);
            if (shape == 0) report(c.name, stats);
            CHECK(stats.grazing_misses <= stats.rays / 50);
            CHECK(stats.max_residual < 16.0 * kEps);
            CHECK(stats.max_front_s_error < 256.0 * kEps);
            boxes_around_surface(
                g, [&](Random& r) { return sample_triangle(g, r); }, c.scale, 2000, random);
            // No: a box off the plane, and one in the plane beyond an edge.
            const glm::dvec3 n = glm::normalize(glm::cross(g.p2 - g.p1, g.p3 - g.p1));
            const glm::dvec3 mid = (g.p1 + g.p2 + g.p3) / 3.0;
            CHECK_FALSE(surface_may_meet(g, Box3{mid + 0.5 * c.scale * n - 0.01 * c.scale,
                                                 mid + 0.5 * c.scale * n + 0.01 * c.scale}));
            const glm::dvec3 beyond = g.p1 + 2.0 * (g.p1 - mid);
            CHECK_FALSE(
                surface_may_meet(g, Box3{beyond - 1e-3 * c.scale, beyond + 1e-3 * c.scale}));
        }
        const TriangleGeometry g{c.offset, c.offset + glm::dvec3(c.scale, 0, 0),
                                 c.offset + glm::dvec3(0, c.scale, 0)};
        CHECK(random_rays_are_finite(g, c.scale, c.offset, 2000, random) > 20);
    }
}

// A floor whose vertices lie at 2^50 (about 1e15) and beyond, seen from a
// few units: t's terms are the vertices' size and its value a few units, so
// t in double cannot tell its own sign, and such a floor once drew nothing
// (exit 0, no word). The plane x + y + z = 0 (its signs flipped at random)
// holds the vertices exactly, so the right parameter is -(n.o) / (n.d)
// from a small origin, good to a few ulps. Tolerance 2^-24 relative: t in
// double is kept only where its bound is below that part of it, and the
// double-double t errs by about 2^-100 of the vertices' size (2^-30 of t at
// 2^70). At 2^80 double-double itself nears 2^-24, so there the hit is only
// asked to be in its place to 1e-3. A missing or false hit is off by all of t.
TEST_CASE("triangle: a huge floor is hit from close by, and not from behind",
          "[runtime][geometry]") {
    Random random(54);
    for (const int e : {10, 30, 50, 60, 70, 80}) {
        INFO("vertices at 2^" << e);
        const double size = std::ldexp(1.0, e);
        int hits = 0;
        for (int i = 0; i < 300; ++i) {
            const glm::dvec3 sign{random.uniform() < 0.5 ? -1.0 : 1.0,
                                  random.uniform() < 0.5 ? -1.0 : 1.0,
                                  random.uniform() < 0.5 ? -1.0 : 1.0};
            const auto on_plane = [&](double a, double b) {
                return sign * glm::dvec3(a, b, -(a + b));
            };
            const TriangleGeometry g{on_plane(-3.0 * size, size), on_plane(3.0 * size, size),
                                     on_plane(0.0, -2.0 * size)};
            const glm::dvec3 n = sign;  // (1, 1, 1) with the signs flipped
            const glm::dvec3 origin = random.in_cube(5.0);
            const double height = glm::dot(n, origin);
            if (std::fabs(height) < 0.1) continue;
            const glm::dvec3 target =
                on_plane(random.uniform(-1.0, 1.0), random.uniform(-1.0, 1.0));
            const glm::dvec3 d = target - origin;
            const double expected = -height / glm::dot(n, d);
            if (!(expected > 0.0)) continue;
            const auto hit = intersect(g, Ray3{origin, d}, 0.0, kInf);
            REQUIRE(hit);
            CHECK(hit->s == Approx(expected).epsilon(e <= 70 ? 0x1p-24 : 1e-3));
            // The point lies on the plane within its own bound (what a
            // shadow ray's start must clear); long double keeps the check's
            // own rounding far below it.
            const long double off = static_cast<long double>(n.x) * hit->point.x +
                                    static_cast<long double>(n.y) * hit->point.y +
                                    static_cast<long double>(n.z) * hit->point.z;
            CHECK(std::fabs(static_cast<double>(off)) <= glm::dot(glm::abs(n), hit->error));
            CHECK_FALSE(intersect(g, Ray3{origin, -d}, 0.0, kInf));
            ++hits;
        }
        CHECK(hits > 200);
    }
}

// A huge triangle one of whose edges passes a few units from the rays, on
// the plane y = 3 (exact at any size): a ray meets it exactly when it
// crosses y = 3 at x > 0.25. In double the sheared vertices round by units
// at 2^60, which once drew such a triangle far past that edge where its
// parameter was formed in double-double (a break-it run, 2026-12-08).
// So no ray may hit beyond the edge, at any size. A ray within the
// vertices' rounding in double of the edge (about 2^-50 of their size) may
// still miss inside it: the watertight test in double decides that first,
// so both ways are asked only up to 2^30, rays within 1e-3 left out.
TEST_CASE("triangle: a huge triangle's edge stays where it is", "[runtime][geometry]") {
    Random random(55);
    for (const int e : {10, 30, 50, 60, 70, 80}) {
        INFO("vertices at 2^" << e);
        const double size = std::ldexp(1.0, e);
        const TriangleGeometry g{{0.25, 3.0, -size}, {0.25, 3.0, size}, {size, 3.0, 0.0}};
        int hits = 0, misses = 0;
        for (int i = 0; i < 400; ++i) {
            const glm::dvec3 origin = random.in_cube(5.0);
            if (std::fabs(origin.y - 3.0) < 0.1) continue;
            const glm::dvec3 target{random.uniform(-1.0, 1.0), 3.0, random.uniform(-1.0, 1.0)};
            if (std::fabs(target.x - 0.25) < 1e-3) continue;
            const auto hit = intersect(g, Ray3{origin, target - origin}, 0.0, kInf);
            if (e <= 30) CHECK(hit.has_value() == (target.x > 0.25));
            if (hit) CHECK(target.x > 0.25);
            if (hit) CHECK(hit->s == Approx(1.0).epsilon(0x1p-24));
            (hit ? hits : misses) += 1;
        }
        CHECK(hits > 100);
        CHECK(misses > 100);
    }
}

TEST_CASE("smooth_triangle: interpolated shading normal", "[runtime][geometry]") {
    const SmoothTriangleGeometry g{{0, 0, 0}, {0, 0, 3}, {1, 0, 0},
                                   {1, 0, 1}, {0, 1, 0}, {0, 1, 1}};
    auto hit = intersect(g, Ray3{{0.0, 0.0, 5.0}, {0.0, 0.0, -1.0}}, 0.0, kInf);  // at p1
    REQUIRE(hit);
    CHECK(hit->normal == glm::dvec3(0.0, 0.0, 1.0));
    CHECK(hit->shading_normal.z == Approx(1.0));
    hit = intersect(g, Ray3{{1.0, 0.0, 5.0}, {0.0, 0.0, -1.0}}, 0.0, kInf);  // at p2
    REQUIRE(hit);
    CHECK(hit->shading_normal.x == Approx(std::sqrt(0.5)));
    CHECK(hit->shading_normal.z == Approx(std::sqrt(0.5)));
    hit = intersect(g, Ray3{{0.25, 0.25, 5.0}, {0.0, 0.0, -1.0}}, 0.0, kInf);
    REQUIRE(hit);
    // Unit normals blended by (0.5, 0.25, 0.25), then normalised.
    const glm::dvec3 blend =
        glm::normalize(0.5 * glm::dvec3(0, 0, 1) + 0.25 * glm::normalize(glm::dvec3(1, 0, 1)) +
                       0.25 * glm::normalize(glm::dvec3(0, 1, 1)));
    CHECK(hit->shading_normal.x == Approx(blend.x));
    CHECK(hit->shading_normal.z == Approx(blend.z));
    CHECK(well_formed(*hit));
    // Zero vertex normals fall back to the geometric normal.
    const SmoothTriangleGeometry zero{{0, 0, 0}, {0, 0, 0}, {1, 0, 0},
                                      {0, 0, 0}, {0, 1, 0}, {0, 0, 0}};
    hit = intersect(zero, Ray3{{0.25, 0.25, 5.0}, {0.0, 0.0, -1.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->shading_normal == glm::dvec3(0.0, 0.0, 1.0));
    CHECK(surface_may_meet(g, Box3{{0.2, 0.2, -0.1}, {0.3, 0.3, 0.1}}));
    CHECK_FALSE(surface_may_meet(g, Box3{{0.2, 0.2, 0.1}, {0.3, 0.3, 0.2}}));
}

TEST_CASE("polygon: outlines, holes, even-odd, POV-Ray's closing rule", "[runtime][geometry]") {
    // A square ring in z = 1 given as POV-Ray would: outer and hole each
    // closed by repeating their first point.
    PolygonGeometry ring;
    for (const glm::dvec2 q :
         pov_points({{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{1, 1}, {1, 3}, {3, 3}, {3, 1}}})) {
        ring.points.push_back({q.x, q.y, 1.0});
    }
    auto down = [](double x, double y) { return Ray3{{x, y, 5.0}, {0.0, 0.0, -1.0}}; };
    auto hit = intersect(ring, down(0.5, 0.5), 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == 4.0);
    CHECK(hit->normal == glm::dvec3(0.0, 0.0, 1.0));  // counter-clockwise seen from +z
    CHECK(hit->point == glm::dvec3(0.5, 0.5, 1.0));
    CHECK(hit->uv.x == Approx(0.5));
    CHECK(hit->uv.y == Approx(0.5));
    CHECK_FALSE(intersect(ring, down(2.0, 2.0), 0.0, kInf));  // the hole
    CHECK_FALSE(intersect(ring, down(5.0, 2.0), 0.0, kInf));  // outside
    CHECK(intersect(ring, down(3.5, 2.0), 0.0, kInf));
    // The last outline left open is closed: same result without its repeat.
    PolygonGeometry open_end = ring;
    open_end.points.pop_back();
    CHECK_FALSE(intersect(open_end, down(2.0, 2.0), 0.0, kInf));
    CHECK(intersect(open_end, down(3.5, 2.0), 0.0, kInf));
    // Clockwise points: the normal points to -z.
    PolygonGeometry clockwise{{{0, 0, 1}, {0, 4, 1}, {4, 4, 1}, {4, 0, 1}}};
    hit = intersect(clockwise, down(1.0, 1.0), 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->normal == glm::dvec3(0.0, 0.0, -1.0));
    CHECK_FALSE(intersect(clockwise, Ray3{{-5, 1, 1}, {1, 0, 0}}, -kInf, kInf));  // in its plane
    CHECK_FALSE(
        intersect(PolygonGeometry{{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}}, down(1, 1), -kInf, kInf));
    CHECK_FALSE(inside(ring, {0.5, 0.5, 1.0}));
}

TEST_CASE("polygon: aimed rays on tilted outlines at every scale, may-meet",
          "[runtime][geometry]") {
    Random random(53);
    const auto outlines = test_outlines();
    const std::vector<glm::dvec2> flat = pov_points(outlines);
    const glm::dvec3 e1 = glm::normalize(glm::dvec3(0.8, 0.1, -0.3));
    const glm::dvec3 e2 = glm::normalize(glm::cross(glm::dvec3(0.2, 0.3, 1.0), e1));
    for (const auto& [scale, origin, distance] :
         {std::tuple{1.0, glm::dvec3(0.0), 5.0}, std::tuple{1.0, glm::dvec3(0.0), 1e6},
          std::tuple{1e-6, glm::dvec3(0.3, 0.1, -0.2), 1e6},
          std::tuple{1e6, glm::dvec3(1e6, -1e6, 0.0), 1e6}}) {
        const Placement place{origin, e1, glm::normalize(e2 - glm::dot(e2, e1) * e1), scale};
        PolygonGeometry g;
        for (const glm::dvec2 q : flat) g.points.push_back(place.at(q));
        const glm::dvec3 normal = glm::normalize(glm::cross(place.e1, place.e2));
        auto sample = [&](Random& r) {
            for (;;) {
                const glm::dvec2 q{r.uniform(0.0, 9.0), r.uniform(0.0, 4.0)};
                if (!inside_by_angles(outlines, q)) continue;
                double edge = kInf;
                for (const auto& outline : outlines) {
                    for (std::size_t i = 0; i < outline.size(); ++i) {
                        const glm::dvec2 a = outline[i], b = outline[(i + 1) % outline.size()];
                        const double t =
                            std::clamp(glm::dot(q - a, b - a) / glm::dot(b - a, b - a), 0.0, 1.0);
                        edge = std::min(edge, glm::length(a + t * (b - a) - q));
                    }
                }
                if (edge < 1e-4) continue;
                SurfaceSample s{place.at(q), normal};
                s.edge_distance = edge * place.scale;
                return s;
            }
        };
        auto residual = [&](const glm::dvec3& p) {
            return plane_residual(g.points[0], g.points[1], g.points[3], p);
        };
        const AimStats stats =
            aim_at_surface(g, sample, residual, scale, distance, true, 1500, random);
        report(scale == 1.0 ? "polygon 1"
                            : (scale < 1.0 ? "polygon 1e-6 from 1e6" : "polygon 1e6 at 1e6"),
               stats);
        CHECK(stats.grazing_misses <= stats.rays / 50);
        CHECK(stats.max_residual < 16.0 * kEps);
        CHECK(stats.max_front_s_error < 256.0 * kEps);
        // Rays aimed at points of the plane outside the region (the hole,
        // beside the star's points) must miss, as the independent test says.
        for (int i = 0; i < 2000; ++i) {
            const glm::dvec2 q{random.uniform(-1.0, 10.0), random.uniform(-1.0, 5.0)};
            const glm::dvec3 target = place.at(q);
            const glm::dvec3 from = target + distance * random.unit_vector();
            const bool expected = inside_by_angles(outlines, q);
            double edge = kInf;
            for (const auto& outline : outlines) {
                for (std::size_t k = 0; k < outline.size(); ++k) {
                    edge = std::min(
                        edge, segment_distance(glm::dvec3(outline[k], 0.0),
                                               glm::dvec3(outline[(k + 1) % outline.size()], 0.0),
                                               glm::dvec3(q, 0.0)));
                }
            }
            if (edge < 1e-3) continue;
            CHECK(intersect(g, Ray3{from, target - from}, 0.0, kInf).has_value() == expected);
        }
        boxes_around_surface(g, sample, scale, 10000, random);
        CHECK(random_rays_are_finite(g, 5.0 * scale, place.at({4.5, 2.0}), 2000, random) > 20);
        // No: a box in the hole, one off the plane over the ring.
        const glm::dvec3 hole = place.at({2.0, 2.0});
        CHECK_FALSE(surface_may_meet(g, Box3{hole - 0.3 * scale, hole + 0.3 * scale}));
        const glm::dvec3 over = place.at({0.5, 0.5}) + 0.5 * scale * normal;
        CHECK_FALSE(surface_may_meet(g, Box3{over - 0.1 * scale, over + 0.1 * scale}));
    }
}

TEST_CASE("polygon: rays through a shared edge hit one of the two", "[runtime][geometry]") {
    // Two polygons sharing the edge x = 1 (a square cut in two), tilted.
    const glm::dvec3 e1 = glm::normalize(glm::dvec3(0.8, 0.1, -0.3));
    const glm::dvec3 e2 = glm::normalize(glm::cross(glm::dvec3(0.2, 0.3, 1.0), e1));
    const Placement place{{0.1, 0.2, 0.3}, e1, e2, 1.0};
    PolygonGeometry left{{place.at({0, 0}), place.at({1, 0}), place.at({1, 1}), place.at({0, 1})}};
    PolygonGeometry right{{place.at({1, 0}), place.at({2, 0}), place.at({2, 1}), place.at({1, 1})}};
    Random random(54);
    int leaks = 0;
    for (int i = 0; i < 3000; ++i) {
        const glm::dvec3 target = place.at({1.0, random.uniform(0.01, 0.99)});
        const glm::dvec3 from = target + random.log_uniform(0.1, 1e6) * random.unit_vector();
        const Ray3 ray{from, target - from};
        if (!intersect(left, ray, 0.0, kInf) && !intersect(right, ray, 0.0, kInf)) ++leaks;
    }
    CHECK(leaks == 0);
}

TEST_CASE("polygon: prepared edges decide as the point list does", "[runtime][geometry]") {
    // prepare_polygon keeps the outlines' edges and projects each end once
    // a ray; the unprepared polygon walks the list (outline.hpp) for each
    // edge. Both must give the same hit, bit for bit: outlines with holes,
    // a repeated point, an outline left open, and more points than a ray
    // projects at once (the list's walk again).
    Random random(71);
    std::vector<glm::dvec2> star;
    for (int k = 0; k < 40; ++k) {  // 40 points: past the stack's 32
        const double a = 2.0 * 3.14159265358979 * k / 40.0;
        const double r = k % 2 ? 1.5 : 4.0;
        star.push_back({4.5 + r * std::cos(a), 2.0 + r * std::sin(a)});
    }
    std::vector<glm::dvec2> repeated = pov_points(test_outlines());
    repeated.insert(repeated.begin() + 2, repeated[2]);  // an edge of zero length
    std::vector<glm::dvec2> open_end = pov_points(test_outlines());
    open_end.pop_back();
    int hits = 0;
    for (const std::vector<glm::dvec2>& flat :
         {pov_points(test_outlines()), repeated, open_end, star}) {
        PolygonGeometry plain;
        for (const glm::dvec2 q : flat) plain.points.push_back({q.x, 0.3 * q.x - 0.2 * q.y, q.y});
        PolygonGeometry prepared = plain;
        hexant::runtime::geometry::prepare_polygon(prepared);
        REQUIRE(prepared.prepared);
        for (int i = 0; i < 4000; ++i) {
            const glm::dvec3 target{random.uniform(-1.0, 10.0), 0.0, random.uniform(-1.0, 5.0)};
            const glm::dvec3 on{target.x, 0.3 * target.x - 0.2 * target.z, target.z};
            const glm::dvec3 from = on + random.uniform(0.5, 20.0) * random.unit_vector();
            const Ray3 ray{from, on - from};
            const auto a = intersect(plain, ray, 0.0, kInf);
            const auto b = intersect(prepared, ray, 0.0, kInf);
            REQUIRE(a.has_value() == b.has_value());
            if (!a) continue;
            ++hits;
            CHECK(a->s == b->s);
            CHECK(a->point == b->point);
            CHECK(a->normal == b->normal);
            CHECK(a->uv == b->uv);
        }
    }
    CHECK(hits > 2000);  // of 16,000 rays: inside and outside were both asked
}
