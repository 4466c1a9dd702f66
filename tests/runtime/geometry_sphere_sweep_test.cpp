// Static ray/sphere_sweep geometry for every spline type: the segments'
// polynomials against POV-Ray's interpolation rules, hits on a two-sphere
// linear sweep of equal radii against an analytic capsule, first hits of
// random rays against an independent reference (sphere tracing the sweep's
// distance function min_u |p - c(u)| - |r(u)|, sampled and refined in long
// double), normals against finite differences of that function, inside()
// against its sign, bounds and surface_may_meet around sampled surface
// points, the same hits at scales 1e-150 and 1e150, and no NaN for extreme
// rays.
#include <vector>

#include "geometry_test_support.hpp"
#include "runtime/geometry/box_queries.hpp"
#include "runtime/objects/sphere_sweep/sphere_sweep_geometry.hpp"

using namespace geometry_test;
using hexant::runtime::geometry::make_sphere_sweep;
using hexant::runtime::geometry::SphereSweepGeometry;
using hexant::runtime::geometry::SweepSpline;

namespace {

struct Spheres {
    std::vector<glm::dvec3> centres;
    std::vector<double> radii;
};

// A bent sweep per spline type, radii varying (one negative: POV-Ray
// squares it).
Spheres spheres(SweepSpline spline) {
    switch (spline) {
        case SweepSpline::linear:
            return {{{-1.5, 0.0, 0.0}, {-0.3, 0.6, 0.2}, {0.8, 0.1, -0.4}, {1.4, 1.0, 0.3}},
                    {0.5, 0.25, -0.35, 0.2}};
        case SweepSpline::b_spline:
            return {{{-2.0, -0.5, 0.0},
                     {-1.0, 0.8, 0.3},
                     {0.0, -0.4, -0.3},
                     {1.0, 0.7, 0.2},
                     {2.0, -0.2, 0.5}},
                    {0.3, 0.6, 0.4, 0.5, 0.2}};
        case SweepSpline::cubic:
            return {{{-2.0, 0.0, 0.0},
                     {-1.0, 0.0, 0.0},
                     {0.0, 0.9, 0.4},
                     {1.0, 0.0, -0.3},
                     {2.0, 0.5, 0.0}},
                    {0.2, 0.3, 0.45, -0.25, 0.3}};
    }
    return {};
}

constexpr SweepSpline kSplines[] = {SweepSpline::linear, SweepSpline::b_spline, SweepSpline::cubic};

using LD = long double;

struct Ref {
    // Object-space segments in long double.
    struct Seg {
        LD c[4][4];  // [power][x, y, z, r]
    };
    std::vector<Seg> segs;
    double size = 1.0;

    explicit Ref(const SphereSweepGeometry& g) {
        size = g.size;
        for (const auto& s : g.segments) {
            Seg r;
            for (int p = 0; p < 4; ++p)
                for (int k = 0; k < 4; ++k) {
                    LD v = (LD)s.coef[p][k] * (LD)g.scale;
                    if (p == 0 && k < 3) v += (LD)g.origin[k];
                    r.c[p][k] = v;
                }
            segs.push_back(r);
        }
    }
    static LD at(const Seg& s, int k, LD u) {
        return ((s.c[3][k] * u + s.c[2][k]) * u + s.c[1][k]) * u + s.c[0][k];
    }
    static LD dist(const Seg& s, LD px, LD py, LD pz, LD u) {
        const LD x = px - at(s, 0, u), y = py - at(s, 1, u), z = pz - at(s, 2, u);
        return std::sqrt(x * x + y * y + z * z) - std::fabs(at(s, 3, u));
    }
    // min over u of |p - c(u)| - |r(u)|: 96 samples a segment, the best
    // refined by golden section.
    LD f(LD px, LD py, LD pz) const {
        LD best = 1e300L;
        for (const Seg& s : segs) {
            constexpr int n = 96;
            int bi = 0;
            LD bv = 1e300L;
            for (int i = 0; i <= n; ++i) {
                const LD v = dist(s, px, py, pz, (LD)i / n);
                if (v < bv) bv = v, bi = i;
            }
            LD a = std::max((LD)0, (LD)(bi - 1) / n), b = std::min((LD)1, (LD)(bi + 1) / n);
            const LD phi = 0.6180339887498948482L;
            LD x1 = b - phi * (b - a), x2 = a + phi * (b - a);
            LD f1 = dist(s, px, py, pz, x1), f2 = dist(s, px, py, pz, x2);
            for (int it = 0; it < 60; ++it) {
                if (f1 < f2) {
                    b = x2, x2 = x1, f2 = f1, x1 = b - phi * (b - a), f1 = dist(s, px, py, pz, x1);
                } else {
                    a = x1, x1 = x2, f1 = f2, x2 = a + phi * (b - a), f2 = dist(s, px, py, pz, x2);
                }
            }
            best = std::min({best, bv, f1, f2});
        }
        return best;
    }
    LD f(const glm::dvec3& p) const { return f(p.x, p.y, p.z); }
};

// Sphere tracing from k = 0 along the unit direction: the first k where
// f <= stop, or none within k_max; `closest` is the least f seen.
struct Trace {
    bool hit = false;
    LD k = 0, closest = 1e300L;
};

Trace trace(const Ref& ref, const glm::dvec3& o, const glm::dvec3& u, LD k_max) {
    Trace t;
    const LD stop = 1e-13L * ref.size;
    LD k = 0;
    for (int i = 0; i < 20000 && k <= k_max; ++i) {
        const LD v = ref.f(o.x + k * u.x, o.y + k * u.y, o.z + k * u.z);
        t.closest = std::min(t.closest, v);
        if (v <= stop) {
            t.hit = true;
            t.k = k;
            return t;
        }
        k += v;
    }
    return t;
}

// A point on the surface: from the centre of sphere u of a random segment
// outward along a random direction to where the distance function changes
// sign (bisection).
SurfaceSample sample_surface(const SphereSweepGeometry& g, const Ref& ref, Random& random) {
    const std::size_t j = static_cast<std::size_t>(random.integer(0, (int)g.segments.size() - 1));
    const double u = random.uniform();
    const auto& s = ref.segs[j];
    const glm::dvec3 c((double)Ref::at(s, 0, u), (double)Ref::at(s, 1, u),
                       (double)Ref::at(s, 2, u));
    const glm::dvec3 n = random.unit_vector();
    LD lo = 0, hi = 4.0L * ref.size;
    for (int it = 0; it < 64; ++it) {
        const LD mid = 0.5L * (lo + hi);
        if (ref.f(c.x + mid * n.x, c.y + mid * n.y, c.z + mid * n.z) <= 0)
            lo = mid;
        else
            hi = mid;
    }
    SurfaceSample q;
    q.point = c + (double)lo * n;
    q.normal = n;
    return q;
}

// The analytic capsule: first k > 0 along unit u from o, in long double.
std::optional<LD> capsule_hit(glm::dvec3 a, glm::dvec3 b, double radius, glm::dvec3 o,
                              glm::dvec3 u) {
    std::optional<LD> best;
    auto take = [&](LD k) {
        if (k > 0 && (!best || k < *best)) best = k;
    };
    const LD ax = a.x, ay = a.y, az = a.z;
    const LD ex = (LD)b.x - ax, ey = (LD)b.y - ay, ez = (LD)b.z - az;
    const LD len2 = ex * ex + ey * ey + ez * ez;
    const LD r2 = (LD)radius * radius;
    // Spheres.
    for (const glm::dvec3 c : {a, b}) {
        const LD wx = (LD)o.x - c.x, wy = (LD)o.y - c.y, wz = (LD)o.z - c.z;
        const LD B = wx * u.x + wy * u.y + wz * u.z;
        const LD C = wx * wx + wy * wy + wz * wz - r2;
        const LD disc = B * B - C;
        if (disc >= 0) take(-B - std::sqrt(disc)), take(-B + std::sqrt(disc));
    }
    // Cylinder side: |w - (w.e/len2) e|^2 = r^2 with w = o + k u - a, 0 <= w.e <= len2.
    const LD wx = (LD)o.x - ax, wy = (LD)o.y - ay, wz = (LD)o.z - az;
    const LD we = wx * ex + wy * ey + wz * ez, ue = (LD)u.x * ex + (LD)u.y * ey + (LD)u.z * ez;
    const LD px = wx - we / len2 * ex, py = wy - we / len2 * ey, pz = wz - we / len2 * ez;
    const LD qx = (LD)u.x - ue / len2 * ex, qy = (LD)u.y - ue / len2 * ey,
             qz = (LD)u.z - ue / len2 * ez;
    const LD A = qx * qx + qy * qy + qz * qz, B = px * qx + py * qy + pz * qz,
             C = px * px + py * py + pz * pz - r2;
    if (A > 0) {
        const LD disc = B * B - A * C;
        if (disc >= 0) {
            for (const LD k : {(-B - std::sqrt(disc)) / A, (-B + std::sqrt(disc)) / A}) {
                const LD t = we + k * ue;
                if (t >= 0 && t <= len2) take(k);
            }
        }
    }
    return best;
}

}  // namespace

TEST_CASE("sphere_sweep segments follow POV-Ray's matrices", "[geometry][sphere_sweep]") {
    using hexant::runtime::geometry::sphere_sweep_segment_count;
    CHECK(sphere_sweep_segment_count(SweepSpline::linear, 2) == 1);
    CHECK(sphere_sweep_segment_count(SweepSpline::b_spline, 4) == 1);
    CHECK(sphere_sweep_segment_count(SweepSpline::cubic, 6) == 3);
    CHECK(sphere_sweep_segment_count(SweepSpline::cubic, 3) == 0);
    for (const SweepSpline spline : kSplines) {
        const Spheres sp = spheres(spline);
        const SphereSweepGeometry g = make_sphere_sweep(spline, sp.centres, sp.radii);
        const Ref ref(g);
        REQUIRE(ref.segs.size() ==
                (std::size_t)sphere_sweep_segment_count(spline, sp.radii.size()));
        for (std::size_t i = 0; i < ref.segs.size(); ++i) {
            for (int k = 0; k < 4; ++k) {
                auto P = [&](std::size_t j) { return k < 3 ? sp.centres[j][k] : sp.radii[j]; };
                const double start = (double)Ref::at(ref.segs[i], k, 0),
                             end = (double)Ref::at(ref.segs[i], k, 1);
                double want_start = 0, want_end = 0;
                switch (spline) {
                    case SweepSpline::linear:
                        want_start = P(i), want_end = P(i + 1);
                        break;
                    case SweepSpline::cubic:
                        want_start = P(i + 1), want_end = P(i + 2);
                        break;
                    case SweepSpline::b_spline:
                        want_start = (P(i) + 4 * P(i + 1) + P(i + 2)) / 6;
                        want_end = (P(i + 1) + 4 * P(i + 2) + P(i + 3)) / 6;
                        break;
                }
                CHECK(start == Approx(want_start).margin(1e-14));
                CHECK(end == Approx(want_end).margin(1e-14));
            }
        }
    }
    // Too few spheres, or a non-finite number: empty.
    CHECK(make_sphere_sweep(SweepSpline::b_spline, {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {1, 1, 1})
              .segments.empty());
    CHECK(
        make_sphere_sweep(SweepSpline::linear, {{0, 0, 0}, {kInf, 0, 0}}, {1, 1}).segments.empty());
}

TEST_CASE("sphere_sweep: linear, equal radii is a capsule", "[geometry][sphere_sweep]") {
    Random random(11);
    const glm::dvec3 a(-1.0, 0.2, 0.3), b(1.5, -0.4, 0.8);
    const double radius = 0.4;
    const SphereSweepGeometry g = make_sphere_sweep(SweepSpline::linear, {a, b}, {radius, radius});
    int hits = 0;
    for (int i = 0; i < 3000; ++i) {
        const glm::dvec3 o = random.in_cube(3.0);
        {  // origins outside (the reference's first surface is then the union's)
            const double t = std::clamp(glm::dot(o - a, b - a) / glm::dot(b - a, b - a), 0.0, 1.0);
            if (glm::length(o - (a + t * (b - a))) <= radius) continue;
        }
        glm::dvec3 u = i % 3 == 0 ? glm::normalize(0.5 * (a + b) + random.in_cube(1.0) - o)
                                  : random.unit_vector();
        const auto want = capsule_hit(a, b, radius, o, u);
        const auto hit = intersect(g, Ray3{o, u}, 0.0, kInf);
        // Grazing rays may go either way.
        if (!want) {
            if (hit) {
                const double f = (double)Ref(g).f(hit->point);
                REQUIRE(std::fabs(f) < 1e-12);
            }
            continue;
        }
        if (!hit) {
            // Only a graze: the chord is tiny.
            const auto far = capsule_hit(a, b, radius, o + (double)*want * u + 1e-7 * u, u);
            INFO("missed capsule at " << (double)*want);
            REQUIRE((!far || (double)*far > 1e-6));
            continue;
        }
        ++hits;
        REQUIRE(well_formed(*hit));
        INFO("ray " << i);
        CHECK(std::fabs(hit->s - (double)*want) <= 1e-12 * (1.0 + (double)*want));
        // The normal: from the nearest axis point.
        const glm::dvec3 p = hit->point;
        const double t = std::clamp(glm::dot(p - a, b - a) / glm::dot(b - a, b - a), 0.0, 1.0);
        const glm::dvec3 n = glm::normalize(p - (a + t * (b - a)));
        CHECK(glm::length(hit->normal - n) < 1e-9);
    }
    CHECK(hits > 500);
}

TEST_CASE("sphere_sweep: first hits against sphere tracing", "[geometry][sphere_sweep]") {
    Random random(5);
    for (const SweepSpline spline : kSplines) {
        const Spheres sp = spheres(spline);
        const SphereSweepGeometry g = make_sphere_sweep(spline, sp.centres, sp.radii);
        REQUIRE(!g.segments.empty());
        const Ref ref(g);
        const Box3 bounds = object_bounds(g);
        const glm::dvec3 c = centre(bounds);
        int hits = 0, checked = 0;
        for (int i = 0; i < 150; ++i) {
            const glm::dvec3 o = c + random.in_cube(3.0 * g.size);
            if (ref.f(o) <= 1e-9L) continue;  // origins outside only
            // Aim at a surface point half the time (rays that hit), else anywhere.
            glm::dvec3 u = random.unit_vector();
            if (i % 2 == 0)
                u = glm::normalize(sample_surface(g, ref, random).point + random.in_cube(0.05) - o);
            ++checked;
            const Trace t = trace(ref, o, u, 10.0 * g.size);
            const auto hit = intersect(g, Ray3{o, u * 2.0}, 0.0, kInf);
            INFO("spline " << (int)spline << " ray " << i);
            if (hit) {
                REQUIRE(well_formed(*hit));
                const double k = 2.0 * hit->s;
                // On the surface, and not beyond the reference's first hit.
                CHECK(std::fabs((double)ref.f(hit->point)) < 1e-11 * g.size);
                if (t.hit) {
                    CHECK(k <= (double)t.k + 1e-9 * g.size);
                    CHECK(k >= (double)t.k - 1e-6 * g.size);  // the tracer stops short by f / cos
                } else {
                    CHECK((double)t.closest < 1e-6 * g.size);  // a graze the tracer passed
                }
                ++hits;
            } else if (t.hit) {
                // A miss only where the ray at most grazes: just past the
                // traced hit it must not be deep inside.
                LD deepest = 0;
                for (int j = 1; j <= 20; ++j)
                    deepest = std::min(deepest, ref.f(o + ((double)t.k + 1e-3 * j * g.size) * u));
                CHECK((double)deepest > -1e-9 * g.size);
            }
        }
        CHECK(checked > 60);
        CHECK(hits > 40);
    }
}

TEST_CASE("sphere_sweep: rays from inside exit where the union ends", "[geometry][sphere_sweep]") {
    Random random(8);
    for (const SweepSpline spline : kSplines) {
        const Spheres sp = spheres(spline);
        const SphereSweepGeometry g = make_sphere_sweep(spline, sp.centres, sp.radii);
        const Ref ref(g);
        int n = 0;
        for (int i = 0; i < 2000 && n < 40; ++i) {
            const glm::dvec3 o = centre(g.bounds) + random.in_cube(0.6 * g.size);
            if (!(ref.f(o) < -1e-3L)) continue;
            ++n;
            REQUIRE(inside(g, o));
            const glm::dvec3 u = random.unit_vector();
            const auto hit = intersect(g, Ray3{o, u}, 0.0, kInf);
            REQUIRE(hit);
            REQUIRE(well_formed(*hit));
            CHECK(std::fabs((double)ref.f(hit->point)) < 1e-11 * g.size);
            CHECK(glm::dot(hit->normal, u) > -1e-9);  // leaving
            // Everything before it is inside.
            for (int j = 1; j < 16; ++j) CHECK(ref.f(o + hit->s * (j / 16.0) * u) < 1e-11L);
        }
        CHECK(n > 10);
    }
}

TEST_CASE("sphere_sweep: normals against finite differences", "[geometry][sphere_sweep]") {
    Random random(9);
    for (const SweepSpline spline : kSplines) {
        const Spheres sp = spheres(spline);
        const SphereSweepGeometry g = make_sphere_sweep(spline, sp.centres, sp.radii);
        const Ref ref(g);
        int compared = 0;
        for (int i = 0; i < 80; ++i) {
            const SurfaceSample q = sample_surface(g, ref, random);
            const glm::dvec3 o = q.point + (0.5 + random.uniform()) * g.size * q.normal +
                                 0.2 * g.size * random.unit_vector();
            const auto hit = intersect(g, Ray3{o, q.point - o}, 0.0, kInf);
            if (!hit) continue;
            REQUIRE(well_formed(*hit));
            const LD h = 1e-6L * g.size;
            const glm::dvec3 p = hit->point;
            glm::dvec3 grad;
            for (int k = 0; k < 3; ++k) {
                glm::dvec3 a = p, b = p;
                a[k] -= (double)h;
                b[k] += (double)h;
                grad[k] = (double)((ref.f(b) - ref.f(a)) / (2 * h));
            }
            // Skip creases (where two parts of the union meet): there the
            // difference quotient is not a unit vector.
            if (std::fabs(glm::length(grad) - 1.0) > 1e-4) continue;
            ++compared;
            INFO("spline " << (int)spline << " point " << p.x << " " << p.y << " " << p.z);
            CHECK(glm::length(hit->normal - grad) < 1e-4);
            CHECK(glm::dot(hit->normal, o - p) > 0.0);  // outward, toward the ray's origin
        }
        CHECK(compared > 30);
    }
}

TEST_CASE("sphere_sweep: inside against the distance function", "[geometry][sphere_sweep]") {
    Random random(13);
    for (const SweepSpline spline : kSplines) {
        const Spheres sp = spheres(spline);
        const SphereSweepGeometry g = make_sphere_sweep(spline, sp.centres, sp.radii);
        const Ref ref(g);
        int in = 0;
        for (int i = 0; i < 1500; ++i) {
            const glm::dvec3 p = centre(g.bounds) + random.in_cube(0.7 * g.size);
            const LD f = ref.f(p);
            if (std::fabs(f) < 1e-9L) continue;
            INFO("point " << p.x << " " << p.y << " " << p.z << " f " << (double)f);
            CHECK(inside(g, p) == (f < 0));
            in += f < 0;
        }
        CHECK(in > 30);
        // A point inside every sphere of a segment (POV-Ray 3.7 misses it).
        const SphereSweepGeometry fat =
            make_sphere_sweep(SweepSpline::linear, {{0, 0, 0}, {0.1, 0, 0}}, {1.0, 1.0});
        CHECK(inside(fat, {0.05, 0.0, 0.0}));
        CHECK(!inside(fat, {0.05, 1.01, 0.0}));
    }
}

TEST_CASE("sphere_sweep: bounds and surface_may_meet hold the surface",
          "[geometry][sphere_sweep]") {
    Random random(21);
    for (const SweepSpline spline : kSplines) {
        const Spheres sp = spheres(spline);
        const SphereSweepGeometry g = make_sphere_sweep(spline, sp.centres, sp.radii);
        const Ref ref(g);
        const Box3 bounds = object_bounds(g);
        auto sampler = [&](Random& r) { return sample_surface(g, ref, r); };
        for (int i = 0; i < 400; ++i) REQUIRE(contains(bounds, sampler(random).point));
        boxes_around_surface(g, sampler, g.size, 400, random);
        // Far away, and deep inside one sphere: no.
        CHECK(!surface_may_meet(g, {bounds.hi + 1.0, bounds.hi + 2.0}));
        const glm::dvec3 c = sp.centres[1];
        if (spline != SweepSpline::b_spline) CHECK(!surface_may_meet(g, {c - 0.01, c + 0.01}));
    }
}

// A small box inside the solid lies on the spheres of some balls (those
// that just reach it) as well as within others: the test must go on to a
// ball that holds it rather than answer "may" at the first that crosses
// it. (Answering "may" there sent a deformed sweep's curved paths inside
// the solid down to a chord every 1e-6 of its size: 10^5 pieces and 18 s
// for one ray through a tapered sweep.)
TEST_CASE("sphere_sweep: small boxes inside the solid are off the surface",
          "[geometry][sphere_sweep]") {
    Random random(22);
    // A capsule along x: the point (x, 0.3, 0) is 0.2 inside it, and on the
    // sphere of the balls centred at x - 0.4 and x + 0.4.
    const SphereSweepGeometry capsule =
        make_sphere_sweep(SweepSpline::linear, {{-1, 0, 0}, {1, 0, 0}}, {0.5, 0.5});
    for (const double width : {1e-3, 1e-6, 1e-9}) {
        for (int i = 0; i < 50; ++i) {
            const glm::dvec3 p(random.uniform(-0.5, 0.5), 0.3, 0.0);
            CHECK(!surface_may_meet(capsule, {p - width, p + width}));
        }
    }
    // The same for every spline kind: points well inside (a box's width
    // below their depth), found where some ball holds them with room.
    for (const SweepSpline spline : kSplines) {
        const Spheres sp = spheres(spline);
        const SphereSweepGeometry g = make_sphere_sweep(spline, sp.centres, sp.radii);
        const Box3 bounds = object_bounds(g);
        int inside_boxes = 0;
        for (int i = 0; i < 20000 && inside_boxes < 100; ++i) {
            const glm::dvec3 p(random.uniform(bounds.lo.x, bounds.hi.x),
                               random.uniform(bounds.lo.y, bounds.hi.y),
                               random.uniform(bounds.lo.z, bounds.hi.z));
            // Its depth: how far inside the ball that holds it best, from
            // 2,001 balls along each segment.
            double depth = -1.0;
            for (const auto& segment : g.segments)
                for (int k = 0; k <= 2000; ++k) {
                    const glm::dvec4 ball = segment.at(k / 2000.0);
                    const glm::dvec3 q = (p - g.origin) / g.scale;
                    depth = std::max(depth, std::fabs(ball.w) - glm::length(q - glm::dvec3(ball)));
                }
            depth *= g.scale;
            if (!(depth > 1e-3 * g.size)) continue;
            const double width = 1e-6 * g.size;
            INFO("point " << p.x << ", " << p.y << ", " << p.z << " depth " << depth);
            CHECK(!surface_may_meet(g, {p - width, p + width}));
            ++inside_boxes;
        }
        CHECK(inside_boxes == 100);
    }
}

TEST_CASE("sphere_sweep: scale invariance and extreme rays", "[geometry][sphere_sweep]") {
    Random random(3);
    for (const SweepSpline spline : kSplines) {
        const Spheres sp = spheres(spline);
        const SphereSweepGeometry g = make_sphere_sweep(spline, sp.centres, sp.radii);
        for (const double scale : {0x1p-500, 0x1p500}) {
            Spheres big = sp;
            for (auto& c : big.centres) c *= scale;
            for (auto& r : big.radii) r *= scale;
            const SphereSweepGeometry h = make_sphere_sweep(spline, big.centres, big.radii);
            REQUIRE(!h.segments.empty());
            for (int i = 0; i < 100; ++i) {
                const glm::dvec3 o = random.in_cube(4.0), u = random.unit_vector();
                const auto a = intersect(g, Ray3{o, u}, 0.0, kInf);
                const auto b = intersect(h, Ray3{o * scale, u}, 0.0, kInf);
                REQUIRE(a.has_value() == b.has_value());
                if (!a) continue;
                CHECK(b->s / scale == Approx(a->s).epsilon(1e-12));
                CHECK(glm::length(a->normal - b->normal) < 1e-9);
                CHECK(inside(h, o * scale) == inside(g, o));
            }
        }
        random_rays_are_finite(g, g.size, centre(g.bounds), 2000, random);
        // Origins and directions at every scale, zero components.
        for (int i = 0; i < 2000; ++i) {
            glm::dvec3 o = random.unit_vector() * random.log_uniform(1e-300, 1e300);
            glm::dvec3 d = random.unit_vector() * random.log_uniform(1e-300, 1e300);
            if (i % 3 == 0) o[random.integer(0, 2)] = 0.0;
            if (i % 4 == 0) d[random.integer(0, 2)] = 0.0;
            if (i % 5 == 0) d = -o * random.log_uniform(1e-300, 1e-100);
            const auto hit = intersect(g, Ray3{o, d}, i % 2 ? -kInf : 0.0, kInf);
            if (hit) REQUIRE(well_formed(*hit));
            (void)inside(g, o);
            (void)surface_may_meet(g, {glm::min(o, o + d), glm::max(o, o + d)});
        }
    }
}
