// Static ray/cylinder, ray/cone and ray/disc geometry: analytic hits (caps,
// open ends, rays along the axis and along a cone's generator lines), rays
// aimed at sampled surface points for radii 1e-6 to 1e6 and origins 1e6
// away, inside() against an independent long double test and the ray
// parity, and surface_may_meet around surface points.
#include "geometry_test_support.hpp"
#include "runtime/objects/cylinder/cone_geometry.hpp"
#include "runtime/objects/cylinder/cylinder_geometry.hpp"
#include "runtime/objects/disc/disc_geometry.hpp"

using namespace geometry_test;
using hexant::runtime::geometry::ConeGeometry;
using hexant::runtime::geometry::CylinderGeometry;
using hexant::runtime::geometry::DiscGeometry;

namespace {

// A frustum as the tests see it, built independently of the library's.
struct Profile {
    glm::dvec3 base, cap;
    double r0, r1;
    bool open;
};

Profile profile(const CylinderGeometry& g) {
    return {g.base, g.cap, g.radius, g.radius, g.open};
}
Profile profile(const ConeGeometry& g) {
    return {g.base, g.cap, g.base_radius, g.cap_radius, g.open};
}

struct Frame {
    glm::dvec3 w, t1, t2;
    double length;
};

Frame frame(const Profile& p) {
    Frame f;
    f.length = glm::length(p.cap - p.base);
    f.w = (p.cap - p.base) / f.length;
    const glm::dvec3 helper =
        std::fabs(f.w.x) < 0.6 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
    f.t1 = glm::normalize(glm::cross(f.w, helper));
    f.t2 = glm::cross(f.w, f.t1);
    return f;
}

SurfaceSample sample_profile(const Profile& p, Random& random) {
    const Frame f = frame(p);
    const double k = (p.r1 - p.r0) / f.length;
    const double phi = random.uniform(0.0, 2.0 * kPi);
    const glm::dvec3 radial = std::cos(phi) * f.t1 + std::sin(phi) * f.t2;
    const int part = p.open ? 0 : random.integer(0, 2);
    SurfaceSample q;
    if (part == 0 || (part == 1 && p.r0 == 0.0) || (part == 2 && p.r1 == 0.0)) {
        const double h = f.length * random.uniform(1e-3, 1.0 - 1e-3);
        const double r = p.r0 + k * h;
        q.point = p.base + h * f.w + r * radial;
        q.normal = (radial - k * f.w) / std::sqrt(1.0 + k * k);
        q.curvature_radius = r * std::sqrt(1.0 + k * k);
        q.edge_distance = std::min(h, f.length - h);
        return q;
    }
    const double r_end = part == 1 ? p.r0 : p.r1;
    const double r = r_end * std::sqrt(random.uniform(1e-6, 1.0 - 1e-3));
    q.point = (part == 1 ? p.base : p.cap) + r * radial;
    q.normal = part == 1 ? -f.w : f.w;
    q.edge_distance = r_end - r;
    return q;
}

// The distance to the surface in the meridian half-plane (height, radius),
// in long double: to the side segment and (closed) the two cap segments.
double profile_residual(const Profile& p, const glm::dvec3& point) {
    const long double dx = (long double)p.cap.x - p.base.x, dy = (long double)p.cap.y - p.base.y,
                      dz = (long double)p.cap.z - p.base.z;
    const long double L = std::sqrt(dx * dx + dy * dy + dz * dz);
    const long double wx = dx / L, wy = dy / L, wz = dz / L;
    const long double fx = (long double)point.x - p.base.x, fy = (long double)point.y - p.base.y,
                      fz = (long double)point.z - p.base.z;
    const long double h = fx * wx + fy * wy + fz * wz;
    const long double qx = fx - h * wx, qy = fy - h * wy, qz = fz - h * wz;
    const long double rad = std::sqrt(qx * qx + qy * qy + qz * qz);
    auto segment = [&](long double h0, long double r0, long double h1, long double r1) {
        const long double ex = h1 - h0, ey = r1 - r0;
        const long double t =
            std::clamp(((h - h0) * ex + (rad - r0) * ey) / (ex * ex + ey * ey), 0.0L, 1.0L);
        const long double ax = h0 + t * ex - h, ay = r0 + t * ey - rad;
        return std::sqrt(ax * ax + ay * ay);
    };
    long double d = segment(0.0L, p.r0, L, p.r1);
    if (!p.open) {
        if (p.r0 > 0) d = std::min(d, segment(0.0L, 0.0L, 0.0L, p.r0));
        if (p.r1 > 0) d = std::min(d, segment(L, 0.0L, L, p.r1));
    }
    return static_cast<double>(d);
}

bool profile_inside(const Profile& p, const glm::dvec3& point) {
    const Frame f = frame(p);
    const glm::dvec3 d = point - p.base;
    const long double h =
        (long double)d.x * f.w.x + (long double)d.y * f.w.y + (long double)d.z * f.w.z;
    const long double a =
        (long double)d.x * f.t1.x + (long double)d.y * f.t1.y + (long double)d.z * f.t1.z;
    const long double b =
        (long double)d.x * f.t2.x + (long double)d.y * f.t2.y + (long double)d.z * f.t2.z;
    const long double r = p.r0 + (p.r1 - p.r0) * h / f.length;
    return h >= 0 && h <= f.length && a * a + b * b <= r * r;
}

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

// The shared battery for cylinders and cones.
template <class G>
void check_frustum(const char* name, const G& g, double distance, Random& random) {
    INFO(name);
    const Profile p = profile(g);
    const Frame f = frame(p);
    const double size = std::max({f.length, p.r0, p.r1});
    const AimStats stats = aim_at_surface(
        g, [&](Random& r) { return sample_profile(p, r); },
        [&](const glm::dvec3& x) { return profile_residual(p, x); }, size, distance, !p.open, 2000,
        random);
    report(name, stats);
    CHECK(stats.grazing_misses <= stats.rays / 50);
    CHECK(stats.max_residual < 16.0 * kEps);
    CHECK(stats.max_front_s_error < 64.0 * kEps);
    CHECK(stats.max_point_mismatch < 16.0 * kEps);
    const glm::dvec3 mid = 0.5 * (p.base + p.cap);
    CHECK(random_rays_are_finite(g, size, mid, 3000, random) > 50);
    boxes_around_surface(
        g, [&](Random& r) { return sample_profile(p, r); }, size, 10000, random);
    for (int i = 0; i < 2000; ++i) {
        const glm::dvec3 x = mid + random.in_cube(1.2 * size);
        if (profile_residual(p, x) < 1e-9 * size) continue;
        const bool expected = profile_inside(p, x);
        CHECK(inside(g, x) == expected);
        if (!p.open) CHECK(expected == (crossings(g, x, random.unit_vector()) % 2 == 1));
    }
    // The test can say no: far away, and (closed) well inside.
    const glm::dvec3 far_corner = mid + 3.0 * size;
    CHECK_FALSE(surface_may_meet(g, Box3{far_corner, far_corner + size}));
    const double r_mid = 0.5 * (p.r0 + p.r1);
    const double inner = 0.2 * std::min(r_mid, 0.5 * f.length);
    CHECK_FALSE(surface_may_meet(g, Box3{mid - inner, mid + inner}));
}

}  // namespace

TEST_CASE("cylinder: analytic hits, caps, open ends, axis-parallel rays", "[runtime][geometry]") {
    const CylinderGeometry g{{0.0, 0.0, 0.0}, {0.0, 2.0, 0.0}, 1.0, false};
    auto hit = intersect(g, Ray3{{-5.0, 1.0, 0.0}, {1.0, 0.0, 0.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == Approx(4.0).epsilon(1e-15));
    CHECK(hit->part == 0);
    CHECK(hit->normal.x == Approx(-1.0));
    CHECK(hit->uv.y == Approx(0.5));
    hit = intersect(g, Ray3{{0.2, 5.0, 0.1}, {0.0, -1.0, 0.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == 3.0);
    CHECK(hit->part == 2);
    CHECK(hit->normal == glm::dvec3(0.0, 1.0, 0.0));
    hit = intersect(g, Ray3{{0.2, -5.0, 0.1}, {0.0, 1.0, 0.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == 5.0);
    CHECK(hit->part == 1);
    CHECK(hit->normal == glm::dvec3(0.0, -1.0, 0.0));
    // Parallel to the axis outside the radius: nothing.
    CHECK_FALSE(intersect(g, Ray3{{1.5, -5.0, 0.0}, {0.0, 1.0, 0.0}}, 0.0, kInf));
    // Open: no caps, so a ray down the axis meets nothing; a slanted one the side.
    const CylinderGeometry open{{0.0, 0.0, 0.0}, {0.0, 2.0, 0.0}, 1.0, true};
    CHECK_FALSE(intersect(open, Ray3{{0.2, 5.0, 0.1}, {0.0, -1.0, 0.0}}, 0.0, kInf));
    hit = intersect(open, Ray3{{0.0, 1.0, 0.0}, {1.0, 0.0, 0.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == Approx(1.0).epsilon(1e-15));
    CHECK(hit->normal.x == Approx(1.0));   // outward even from inside
    CHECK(inside(open, {0.0, 1.0, 0.0}));  // open changes no inside
    // Degenerate cylinders have no hits.
    CHECK_FALSE(intersect(CylinderGeometry{{0, 0, 0}, {0, 0, 0}, 1.0, false},
                          Ray3{{-5, 0, 0}, {1, 0, 0}}, 0.0, kInf));
    CHECK_FALSE(intersect(CylinderGeometry{{0, 0, 0}, {0, 1, 0}, 0.0, false},
                          Ray3{{-5, 0.5, 0}, {1, 0, 0}}, 0.0, kInf));
    const Box3 b = object_bounds(CylinderGeometry{{0, 0, 0}, {3, 4, 0}, 1.0, false});
    CHECK(b.lo.x == Approx(-0.8));
    CHECK(b.hi.x == Approx(3.8));
    CHECK(b.lo.y == Approx(-0.6));
    CHECK(b.hi.y == Approx(4.6));
    CHECK(b.lo.z == Approx(-1.0));
}

TEST_CASE("cone: analytic hits, apex, rays along a generator line", "[runtime][geometry]") {
    const ConeGeometry g{{0.0, 0.0, 0.0}, 1.0, {0.0, 1.0, 0.0}, 0.0, false};
    auto hit = intersect(g, Ray3{{-5.0, 0.5, 0.0}, {1.0, 0.0, 0.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == Approx(4.5).epsilon(1e-15));
    CHECK(hit->part == 0);
    CHECK(hit->normal.x == Approx(-std::sqrt(0.5)));
    CHECK(hit->normal.y == Approx(std::sqrt(0.5)));
    // Parallel to a generator line: the quadratic's leading term vanishes.
    hit = intersect(g, Ray3{{-2.0, -1.2, 0.0}, {1.0, 1.0, 0.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == Approx(1.2).epsilon(1e-15));
    CHECK(hit->part == 1);
    hit = intersect(g, Ray3{{-2.0, -1.2, 0.0}, {1.0, 1.0, 0.0}}, 1.2, kInf);
    REQUIRE(hit);
    CHECK(hit->s == Approx(2.1).epsilon(1e-14));
    CHECK(hit->part == 0);
    CHECK(hit->point.x == Approx(0.1));
    // Through the apex along the axis from above.
    hit = intersect(g, Ray3{{0.0, 3.0, 0.0}, {0.0, -1.0, 0.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == Approx(2.0).epsilon(1e-15));
    CHECK(well_formed(*hit));
    // The other nappe of the double cone is not part of the shape.
    CHECK_FALSE(intersect(g, Ray3{{-5.0, 1.5, 0.0}, {1.0, 0.0, 0.0}}, 0.0, kInf));
    CHECK_FALSE(intersect(g, Ray3{{-5.0, -0.5, 0.0}, {1.0, 0.0, 0.0}}, 0.0, kInf));
    // Inverted cone, negative radius: empty.
    CHECK_FALSE(intersect(ConeGeometry{{0, 0, 0}, -1.0, {0, 1, 0}, 1.0, false},
                          Ray3{{-5, 0.5, 0}, {1, 0, 0}}, 0.0, kInf));
    CHECK(inside(g, {0.0, 0.5, 0.4}));
    CHECK_FALSE(inside(g, {0.0, 0.5, 0.6}));
}

TEST_CASE("cylinder and cone: aimed rays at every scale, inside, may-meet", "[runtime][geometry]") {
    Random random(31);
    const glm::dvec3 tilt = glm::normalize(glm::dvec3(0.3, 1.0, -0.2));
    check_frustum("cylinder r=0.5 near", CylinderGeometry{{0, 0, 0}, {0, 2, 0}, 0.5, false}, 4.0,
                  random);
    check_frustum("cylinder tilted from 1e6",
                  CylinderGeometry{{1, 2, 3}, glm::dvec3(1, 2, 3) + 2.0 * tilt, 0.7, false}, 1e6,
                  random);
    check_frustum(
        "cylinder r=1e-6 from 1e6",
        CylinderGeometry{{0.3, 0.1, -0.2}, glm::dvec3(0.3, 0.1, -0.2) + 3e-6 * tilt, 1e-6, false},
        1e6, random);
    check_frustum(
        "cylinder r=1e-6 needle from 1",
        CylinderGeometry{{0.3, 0.1, -0.2}, glm::dvec3(0.3, 0.1, -0.2) + tilt, 1e-6, false}, 1.0,
        random);
    check_frustum(
        "cylinder r=1e6 at 1e6 from 1e6",
        CylinderGeometry{{1e6, 0, -1e6}, glm::dvec3(1e6, 0, -1e6) + 2e6 * tilt, 1e6, false}, 1e6,
        random);
    check_frustum("cylinder open", CylinderGeometry{{0, 0, 0}, {0, 2, 0}, 0.5, true}, 4.0, random);
    check_frustum("cone frustum near", ConeGeometry{{0, 0, 0}, 1.0, {0, 2, 0}, 0.25, false}, 4.0,
                  random);
    check_frustum("cone to apex tilted from 1e6",
                  ConeGeometry{{1, 2, 3}, 0.7, glm::dvec3(1, 2, 3) + 2.0 * tilt, 0.0, false}, 1e6,
                  random);
    check_frustum(
        "cone widening r=1e-6 from 1e6",
        ConeGeometry{{0.3, 0.1, -0.2}, 1e-6, glm::dvec3(0.3, 0.1, -0.2) + 2e-6 * tilt, 3e-6, false},
        1e6, random);
    check_frustum(
        "cone r=1e6 at 1e6 from 1e6",
        ConeGeometry{{1e6, 0, -1e6}, 1e6, glm::dvec3(1e6, 0, -1e6) + 2e6 * tilt, 2e5, false}, 1e6,
        random);
    check_frustum("cone open", ConeGeometry{{0, 0, 0}, 1.0, {0, 2, 0}, 0.25, true}, 4.0, random);
}

TEST_CASE("disc: hits, hole, parallel rays, scales, may-meet", "[runtime][geometry]") {
    const DiscGeometry g{{0.0, 0.0, 0.0}, {0.0, 0.0, 2.0}, 2.0, 1.0};
    auto hit = intersect(g, Ray3{{1.5, 0.0, 5.0}, {0.0, 0.0, -1.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == 5.0);
    CHECK(hit->normal == glm::dvec3(0.0, 0.0, 1.0));
    CHECK(hit->uv.y == 0.75);
    hit = intersect(g, Ray3{{1.5, 0.0, -5.0}, {0.0, 0.0, 1.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->normal == glm::dvec3(0.0, 0.0, 1.0));  // its own side, not flipped
    CHECK_FALSE(intersect(g, Ray3{{0.5, 0.0, 5.0}, {0.0, 0.0, -1.0}}, 0.0, kInf));  // the hole
    CHECK_FALSE(intersect(g, Ray3{{2.5, 0.0, 5.0}, {0.0, 0.0, -1.0}}, 0.0, kInf));
    CHECK_FALSE(intersect(g, Ray3{{-5.0, 0.0, 0.0}, {1.0, 0.0, 0.0}}, -kInf, kInf));  // parallel
    CHECK_FALSE(inside(g, {1.5, 0.0, 0.0}));

    Random random(32);
    const glm::dvec3 n = glm::normalize(glm::dvec3(-0.4, 0.5, 0.8));
    const glm::dvec3 t1 = glm::normalize(glm::cross(n, glm::dvec3(1.0, 0.0, 0.0)));
    const glm::dvec3 t2 = glm::cross(n, t1);
    struct Case {
        const char* name;
        DiscGeometry g;
        double distance;
    };
    const Case cases[] = {
        {"disc r=1 near", {{0.1, 0.2, 0.3}, n, 1.0, 0.3}, 3.0},
        {"disc r=1e-6 from 1e6", {{0.1, 0.2, 0.3}, n, 1e-6, 0.0}, 1e6},
        {"disc r=1e6 at 1e6 from 1e6", {{1e6, 2e6, -1e6}, n, 1e6, 2e5}, 1e6},
    };
    for (const Case& c : cases) {
        INFO(c.name);
        const double R = c.g.radius, hole = c.g.hole_radius;
        auto sample = [&](Random& r) {
            const double phi = r.uniform(0.0, 2.0 * kPi);
            const double rad = std::sqrt(r.uniform(hole * hole, R * R));
            const double margin = std::min(R - rad, rad - hole);
            const double rr = margin < 1e-3 * R ? 0.5 * (R + hole) : rad;
            SurfaceSample q{c.g.center + rr * (std::cos(phi) * t1 + std::sin(phi) * t2), n};
            q.edge_distance = std::min(R - rr, rr - hole);
            return q;
        };
        auto residual = [&](const glm::dvec3& x) {
            const long double fx = (long double)x.x - c.g.center.x,
                              fy = (long double)x.y - c.g.center.y,
                              fz = (long double)x.z - c.g.center.z;
            const long double off = fx * n.x + fy * n.y + fz * n.z;
            const long double px = fx - off * n.x, py = fy - off * n.y, pz = fz - off * n.z;
            const long double rad = std::sqrt(px * px + py * py + pz * pz);
            const long double excess = std::max({rad - R, hole - rad, 0.0L});
            return static_cast<double>(std::sqrt(off * off + excess * excess));
        };
        const AimStats stats =
            aim_at_surface(c.g, sample, residual, R, c.distance, true, 2000, random);
        report(c.name, stats);
        CHECK(stats.grazing_misses <= stats.rays / 50);
        CHECK(stats.max_residual < 16.0 * kEps);
        CHECK(stats.max_front_s_error < 64.0 * kEps);
        CHECK(stats.max_point_mismatch < 16.0 * kEps);
        CHECK(random_rays_are_finite(c.g, R, c.g.center, 3000, random) > 50);
        boxes_around_surface(c.g, sample, R, 10000, random);
        // No: a box in the hole's middle, and one off the plane.
        if (hole > 0.0) {
            CHECK_FALSE(
                surface_may_meet(c.g, Box3{c.g.center - 0.3 * hole, c.g.center + 0.3 * hole}));
        }
        CHECK_FALSE(surface_may_meet(
            c.g, Box3{c.g.center + 0.5 * R * n - 0.1 * R, c.g.center + 0.5 * R * n + 0.1 * R}));
    }
}
