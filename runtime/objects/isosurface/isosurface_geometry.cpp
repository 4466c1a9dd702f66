#include "runtime/objects/isosurface/isosurface_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "runtime/geometry/box_queries.hpp"
#include "runtime/geometry/local_ray.hpp"
#include "runtime/geometry/stable_arithmetic.hpp"

namespace hexant::runtime::geometry {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// The shortest piece without a sign change that the search still splits,
// relative to the container's size: a ray that grazes the surface crosses
// it over a stretch of about this length or longer.
constexpr double kFineLeaf = 1e-7;
// Pieces one ray may visit before the search looks at piece ends only.
constexpr int kPieceBudget = 1 << 16;
// Pieces held at once: one more than the depth of halving, which ends at
// adjacent doubles (64 levels at most for a container of any size).
constexpr int kStackSize = 160;

// F - T at p; NaN is outside (no hit, not inside).
double value(const IsosurfaceGeometry& g, const glm::dvec3& p) {
    return g.function.at(p, g.time) - g.threshold;
}
bool out(double v) {
    return !(v <= 0.0);
}

// A range holding F - T over the box of the segment from a to b.
Interval range(const IsosurfaceGeometry& g, const glm::dvec3& a, const glm::dvec3& b) {
    const IntervalBox box{Interval(std::min(a.x, b.x), std::max(a.x, b.x)),
                          Interval(std::min(a.y, b.y), std::max(a.y, b.y)),
                          Interval(std::min(a.z, b.z), std::max(a.z, b.z))};
    return g.function.over(box, Interval(g.time)) - Interval(g.threshold);
}
// Written so that a NaN end answers yes.
bool holds_zero(const Interval& r) {
    return !(r.lo > 0.0 || r.hi < 0.0);
}

glm::dvec3 container_centre(const IsosurfaceGeometry& g) {
    return g.sphere ? g.center : 0.5 * g.lo + 0.5 * g.hi;
}
double container_size(const IsosurfaceGeometry& g) {
    return g.sphere ? std::fabs(g.radius) : 0.5 * safe_length(g.hi - g.lo);
}

// The stretch [k0, k1] of the local ray inside the container, with the
// walls' outward normals where it enters and leaves.
bool clip(const IsosurfaceGeometry& g, const LocalRay& r, double& k0, double& k1, glm::dvec3& n0,
          glm::dvec3& n1) {
    if (g.sphere) {
        // |o + k u - c|^2 = R^2 with |u| = 1.
        const glm::dvec3 oc = r.origin - g.center;
        const double b = glm::dot(oc, r.unit);
        const double c = glm::dot(oc, oc) - g.radius * g.radius;
        const double disc = b * b - c;
        if (!(disc >= 0.0)) return false;
        const double root = std::sqrt(disc);
        k0 = -b - root;
        k1 = -b + root;
        n0 = (r.at(k0) - g.center) / g.radius;
        n1 = (r.at(k1) - g.center) / g.radius;
        return k0 <= k1;
    }
    k0 = -kInf;
    k1 = kInf;
    for (int i = 0; i < 3; ++i) {
        if (r.unit[i] != 0.0) {
            double a = (g.lo[i] - r.origin[i]) / r.unit[i], b = (g.hi[i] - r.origin[i]) / r.unit[i];
            glm::dvec3 na(0.0), nb(0.0);
            na[i] = -1.0;
            nb[i] = 1.0;
            if (a > b) {
                std::swap(a, b);
                std::swap(na, nb);
            }
            if (a > k0) k0 = a, n0 = na;
            if (b < k1) k1 = b, n1 = nb;
        } else if (!(r.origin[i] >= g.lo[i] && r.origin[i] <= g.hi[i])) {
            return false;
        }
    }
    return k0 <= k1 && std::isfinite(k0) && std::isfinite(k1);
}

// The first crossing of F = T on [k0, k1] of the local ray, front first:
// the last point before it and the first past it.
std::optional<std::pair<double, double>> first_crossing(const IsosurfaceGeometry& g,
                                                        const LocalRay& r, double k0, double k1) {
    const double fine = kFineLeaf * container_size(g);
    const auto f = [&](double k) { return value(g, r.at(k)); };
    struct Piece {
        double a, b, fa, fb;
    };
    Piece stack[kStackSize];
    int top = 0;
    stack[top++] = {k0, k1, f(k0), f(k1)};
    int budget = kPieceBudget;
    const auto refine = [&](double lo, double hi, double flo) {
        for (int i = 0; i < 200; ++i) {
            const double m = 0.5 * (lo + hi);
            if (!(m > lo && m < hi)) break;
            const double fm = f(m);
            if (out(fm) == out(flo))
                lo = m, flo = fm;
            else
                hi = m;
        }
        return std::pair{lo, hi};  // adjacent doubles about the crossing
    };
    // Whether F may equal T on a piece: by F's interval bound, or (sampled)
    // by max_gradient as POV-Ray bounds it.
    const auto may_cross = [&](const Piece& piece) {
        const glm::dvec3 a = r.at(piece.a), b = r.at(piece.b);
        if (!g.sampled) return holds_zero(range(g, a, b));
        return !(std::fabs(piece.fa + piece.fb) > g.max_gradient * safe_length(b - a));
    };
    while (top > 0) {
        const Piece piece = stack[--top];
        const bool split = budget-- > 0;
        if (split && !may_cross(piece)) continue;
        const double mid = 0.5 * (piece.a + piece.b);
        const bool halvable = mid > piece.a && mid < piece.b;
        const double fm = halvable ? f(mid) : piece.fb;
        // A piece with a sign change is a leaf at the scene's accuracy; one
        // without splits on to kFineLeaf of the container (a ray grazing
        // the surface crosses it over a short stretch only).
        const bool crosses = out(piece.fa) != out(fm) || out(fm) != out(piece.fb);
        const double leaf = crosses || g.sampled ? g.accuracy : fine;
        if (split && halvable && piece.b - piece.a > leaf && top + 2 <= kStackSize) {
            stack[top++] = {mid, piece.b, fm, piece.fb};
            stack[top++] = {piece.a, mid, piece.fa, fm};
            continue;
        }
        // A leaf: a sign change in its front half, else in its back half.
        if (out(piece.fa) != out(fm)) return refine(piece.a, mid, piece.fa);
        if (out(fm) != out(piece.fb)) return refine(mid, piece.b, fm);
    }
    return std::nullopt;
}

// POV-Ray's normal (IsoSurface::Normal): forward differences over
// `accuracy`. Not the exact gradient: where F turns within that step (the
// ridges of a cactus near its axis) the two differ by tenths, and the
// scene's look, and the normals trace() hands it, are POV-Ray's.
glm::dvec3 difference_gradient(const IsosurfaceGeometry& g, const glm::dvec3& p) {
    const double f = g.function.at(p, g.time);
    glm::dvec3 n;
    for (int axis = 0; axis < 3; ++axis) {
        glm::dvec3 q = p;
        q[axis] += g.accuracy;
        n[axis] = g.function.at(q, g.time) - f;
    }
    return n;
}

SurfaceHit make_hit(const IsosurfaceGeometry& g, const LocalRay& r, double k, int part,
                    const glm::dvec3& wall_normal) {
    SurfaceHit hit;
    hit.s = r.to_s(k);
    hit.point = r.at(k);
    hit.part = part;
    hit.uv = glm::dvec2(0.0);
    glm::dvec3 n = wall_normal;
    if (part == 0) {
        n = difference_gradient(g, hit.point);
        const double length = safe_length(n);
        n = length > 0.0 && std::isfinite(length) ? n / length : glm::dvec3(1.0, 0.0, 0.0);
    }
    hit.normal = n;
    hit.shading_normal = n;
    // The point's distance from the surface: its coordinates' rounding,
    // and on F = T the rounding of F there (the width of its interval at
    // the point) over the gradient's length.
    double along = 0.0;
    if (part == 0 && !g.sampled) {
        const glm::dvec3& p = hit.point;
        const Interval at_p =
            g.function.over({Interval(p.x), Interval(p.y), Interval(p.z)}, Interval(g.time));
        const double slope = safe_length(g.function.gradient(p, g.time));
        if (slope > 0.0) along = at_p.width() / slope;
        if (!std::isfinite(along)) along = 0.0;
    }
    hit.error = rounding_gamma(64) * (glm::abs(hit.point) + container_size(g)) + along;
    return hit;
}

}  // namespace

std::optional<SurfaceHit> intersect(const IsosurfaceGeometry& g, const Ray3& ray, double s_min,
                                    double s_max) {
    const auto local = local_ray(ray, container_centre(g), container_size(g));
    if (!local) return std::nullopt;
    double k0, k1;
    glm::dvec3 n0(0.0), n1(0.0);
    if (!clip(g, *local, k0, k1, n0, n1)) return std::nullopt;
    const double k_min = local->to_t(s_min), k_max = local->to_t(s_max);
    const auto in_range = [&](double k) {
        const double s = local->to_s(k);
        return s > s_min && s < s_max;
    };
    // Into the solid through a wall.
    if (!g.open && in_range(k0) && !out(value(g, local->at(k0)))) {
        SurfaceHit hit = make_hit(g, *local, k0, 1, n0);
        if (is_finite(hit)) return hit;
    }
    const double a = std::max(k0, k_min), b = std::min(k1, k_max);
    if (a <= b) {
        if (const auto k = first_crossing(g, *local, a, b)) {
            // The point past the crossing, or the one before it where that
            // is beyond s_max (a crossing at the end of a curved path's
            // chord is the next chord's start, which begins inside).
            const double at = in_range(k->second) ? k->second : k->first;
            if (in_range(at)) {
                SurfaceHit hit = make_hit(g, *local, at, 0, glm::dvec3(0.0));
                if (is_finite(hit)) return hit;
            }
        }
    }
    // Out of the solid through a wall.
    if (!g.open && in_range(k1) && !out(value(g, local->at(k1)))) {
        SurfaceHit hit = make_hit(g, *local, k1, 1, n1);
        if (is_finite(hit)) return hit;
    }
    return std::nullopt;
}

bool inside(const IsosurfaceGeometry& g, glm::dvec3 p) {
    if (g.sphere) {
        const glm::dvec3 d = p - g.center;
        if (!(glm::dot(d, d) <= g.radius * g.radius)) return false;
    } else if (!contains(Box3{g.lo, g.hi}, p)) {
        return false;
    }
    return !out(value(g, p));
}

Box3 object_bounds(const IsosurfaceGeometry& g) {
    if (g.sphere) {
        const double r = std::fabs(g.radius);
        return {g.center - r, g.center + r};
    }
    return {g.lo, g.hi};
}

bool surface_may_meet(const IsosurfaceGeometry& g, const Box3& box) {
    const Box3 bounds = object_bounds(g);
    const Box3 wide = widened(box, meet_slack(box, container_size(g) + max_abs(bounds.hi)));
    if (!overlaps(wide, bounds)) return false;
    const Box3 part{glm::max(wide.lo, bounds.lo), glm::min(wide.hi, bounds.hi)};
    const Interval r = range(g, part.lo, part.hi);
    if (holds_zero(r)) return true;
    if (g.open || r.lo > 0.0) return false;
    // All of it in the solid: surface only where it reaches a wall.
    if (g.sphere) {
        glm::dvec3 far;
        for (int i = 0; i < 3; ++i)
            far[i] =
                std::max(std::fabs(part.lo[i] - g.center[i]), std::fabs(part.hi[i] - g.center[i]));
        return glm::dot(far, far) >= g.radius * g.radius;
    }
    for (int i = 0; i < 3; ++i)
        if (part.lo[i] <= bounds.lo[i] || part.hi[i] >= bounds.hi[i]) return true;
    return false;
}

}  // namespace hexant::runtime::geometry
