#include "runtime/objects/julia_fractal/julia_fractal_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "runtime/geometry/box_queries.hpp"
#include "runtime/geometry/local_ray.hpp"
#include "runtime/geometry/stable_arithmetic.hpp"

namespace hexant::runtime::geometry {

namespace {

constexpr double kTolerance = 1e-7;    // fractal.cpp's Fractal_Tolerance
constexpr double kPovEpsilon = 1e-10;  // POV-Ray's EPSILON
// The most steps of one march: far more than any scene needs (the largest
// sphere, radius 4, at precision 10^5 takes 8 * 10^5), bounded work for a
// hostile precision.
constexpr long kMaxSteps = 1L << 22;
// Rays starting farther than 4 * kFarRadii radii away are restated
// (local_ray's kRecentreSizes is 4).
constexpr double kFarRadii = 250.0;

double dot3(const glm::dvec3& a, const glm::dvec3& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;  // POV-Ray's VDot, in its order
}

}  // namespace

JuliaFractalGeometry make_julia_fractal(const std::array<double, 4>& c, JuliaAlgebra algebra,
                                        JuliaFunction function, Complex exponent, int iterations,
                                        double precision, const std::array<double, 4>& slice,
                                        double slice_distance) {
    JuliaFractalGeometry g;
    g.c = c;
    g.algebra = algebra;
    g.function = function;
    g.exponent = exponent;
    g.iterations = std::max(iterations, 1);
    g.precision = 1.0 / std::max(precision, 1.0);
    // Parse_Julia_Fractal's slice: normalised; refused when (nearly) zero or
    // parallel to the 3D space.
    const double p =
        slice[0] * slice[0] + slice[1] * slice[1] + slice[2] * slice[2] + slice[3] * slice[3];
    g.slice_distance = slice_distance;
    bool finite = std::isfinite(p) && std::isfinite(slice_distance) && std::isfinite(precision) &&
                  std::isfinite(exponent.x) && std::isfinite(exponent.y);
    for (const double v : c) finite = finite && std::isfinite(v);
    if (!finite || std::fabs(p) < kPovEpsilon || std::fabs(slice[3]) < kPovEpsilon) return g;
    const double length = std::sqrt(p);
    for (int i = 0; i < 4; ++i) g.slice[i] = slice[i] / length;
    if (!(std::fabs(g.slice[3]) > 0.0)) return g;
    // Compute_BBox.
    double r;
    if (algebra == JuliaAlgebra::quaternion) {
        r = 1.0 + std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2] + c[3] * c[3]);
        r += kTolerance;  // POV-Ray: "fix bug when Julia_Parameter exactly 0"
        if (r > 2.0) r = 2.0;
        g.exit_value = r * r + kTolerance;
    } else {
        r = 4.0;
        g.exit_value = 16.0;
    }
    g.radius = r;
    g.radius_squared = r * r;
    g.valid = true;
    return g;
}

double julia_reach(const JuliaFractalGeometry& g) {
    // A point beyond sqrt(exit_value) escapes at the first step: its |q0|^2
    // is at least its |p|^2 (the relative slack covers the norm's rounding).
    return std::max(g.radius, std::sqrt(g.exit_value)) * (1.0 + 1e-14);
}

std::optional<SurfaceHit> intersect(const JuliaFractalGeometry& g, const Ray3& ray, double s_min,
                                    double s_max) {
    if (!g.valid || !is_finite(ray.origin) || !is_finite(ray.direction)) return std::nullopt;
    // Into the fractal's space with a unit direction (All_Intersections).
    glm::dvec3 direction = ray.direction;
    const double len2 = dot3(direction, direction);
    if (!(len2 > 0.0) || !std::isfinite(len2)) return std::nullopt;
    double len = 1.0;
    if (len2 != 1.0) {
        len = 1.0 / std::sqrt(len2);
        direction *= len;
    }
    // A ray from far away (beyond 1000 radii; POV-Ray's camera rays start
    // nearer) is restated near the sphere first, as local_ray does, or its
    // points would carry the ulps of its far origin.
    glm::dvec3 origin = ray.origin;
    double s_offset = 0.0;
    if (const auto local = local_ray(ray, glm::dvec3(0.0), kFarRadii * g.radius);
        local && local->s_offset != 0.0) {
        origin = local->origin;
        s_offset = local->s_offset;
    }

    // F_Bound: Sphere::Intersect with the sphere at the origin.
    const glm::dvec3 to_centre = -origin;
    const double oc2 = dot3(to_centre, to_centre);
    const double closest = dot3(to_centre, direction);
    if (oc2 >= g.radius_squared && closest < kPovEpsilon) return std::nullopt;
    const double half2 = g.radius_squared - oc2 + closest * closest;
    if (!(half2 > kPovEpsilon)) return std::nullopt;
    const double half = std::sqrt(half2);
    double depth = closest - half;
    double depth_max = closest + half;
    if (depth_max < kTolerance) return std::nullopt;
    if (depth < kTolerance) depth = kTolerance;
    // hexant's range of s (depth * len): the march starts no earlier than
    // s_min and ends by s_max.
    const double depth_lo = (s_min - s_offset) / len, depth_hi = (s_max - s_offset) / len;
    if (depth_lo > depth) depth = depth_lo;
    if (depth_hi < depth_max) depth_max = depth_hi;
    if (!(depth < depth_max)) return std::nullopt;

    JuliaStack& stack = thread_julia_stack();
    stack.ensure(g.iterations);
    glm::dvec3 next = direction * depth + origin;
    double dist = 0.0, dist_next = 0.0;
    bool current = julia_distance_iterate(g, next, direction, dist, stack);
    // A ray starting inside: a step on first.
    if (current) {
        next += 2.0 * kTolerance * direction;
        depth += 2.0 * kTolerance;
        if (depth > depth_max) return std::nullopt;
        current = julia_distance_iterate(g, next, direction, dist, stack);
    }
    // Advance until the inside test changes, keeping the last point in ipoint.
    glm::dvec3 ipoint;
    long steps = 0;
    for (;;) {
        if (!(dist >= g.precision)) dist = g.precision;  // (a NaN estimate too)
        depth += dist;
        if (depth > depth_max || ++steps > kMaxSteps) return std::nullopt;
        ipoint = next;
        next += dist * direction;
        const bool next_inside = julia_distance_iterate(g, next, direction, dist_next, stack);
        if (next_inside != current) {
            depth -= dist;
            break;
        }
        dist = dist_next;
    }
    // Then polish the crossing by halving.
    bool last = false;
    while (dist > kTolerance) {
        dist *= 0.5;
        const glm::dvec3 mid = ipoint + dist * direction;
        last = julia_iterate(g, mid, stack);
        if (last == current) {
            ipoint = mid;
            depth += dist;
            if (depth > depth_max) return std::nullopt;
        }
    }
    // The stack of the point whose normal is taken.
    if (!current) {
        ipoint += dist * direction;
        depth += dist;
        julia_iterate(g, ipoint, stack);
    } else if (last != current) {
        julia_iterate(g, ipoint, stack);
    }
    // (POV-Ray checks no end after that last step: where the halving never
    // moved, as where the function iteration's start differs from the
    // march's, it can leave the sphere, and the object's bound.)
    if (depth > depth_max) return std::nullopt;

    SurfaceHit hit;
    hit.s = s_offset + depth * len;
    if (!(hit.s > s_min && hit.s < s_max)) return std::nullopt;
    hit.point = ipoint;
    hit.part = 0;
    hit.uv = glm::dvec2(0.0);
    glm::dvec3 n = julia_normal(g, g.iterations, stack);
    const double n_length = is_finite(n) ? safe_length(n) : 0.0;
    n = n_length > 0.0 && std::isfinite(n_length) ? n / n_length : -direction;
    hit.normal = n;
    hit.shading_normal = n;
    // The point lies within the last halving step of a crossing along the ray.
    hit.error = glm::dvec3(std::max(dist, kTolerance)) +
                rounding_gamma(64) * (glm::abs(hit.point) + g.radius);
    if (!is_finite(hit)) return std::nullopt;
    return hit;
}

bool inside(const JuliaFractalGeometry& g, glm::dvec3 p) {
    if (!g.valid) return false;
    JuliaStack& stack = thread_julia_stack();
    stack.ensure(g.iterations);
    return julia_iterate(g, p, stack);
}

Box3 object_bounds(const JuliaFractalGeometry& g) {
    if (!g.valid) return {glm::dvec3(0.0), glm::dvec3(0.0)};
    const double r = julia_reach(g);
    return {glm::dvec3(-r), glm::dvec3(r)};
}

bool surface_may_meet(const JuliaFractalGeometry& g, const Box3& box) {
    if (!g.valid) return false;
    const double reach = julia_reach(g);
    // Hits lie within a halving step of the crossing they report.
    const Box3 wide = widened(box, meet_slack(box, reach) + 4.0 * kTolerance);
    const Box3 bounds = object_bounds(g);
    if (!overlaps(wide, bounds)) return false;
    glm::dvec3 nearest;
    for (int i = 0; i < 3; ++i) {
        if (!(wide.lo[i] <= wide.hi[i])) return true;  // NaN: may meet
        nearest[i] = std::clamp(0.0, wide.lo[i], wide.hi[i]);
    }
    if (safe_length(nearest) > reach) return false;
    return !julia_uniform_over(g, glm::max(wide.lo, bounds.lo), glm::min(wide.hi, bounds.hi));
}

}  // namespace hexant::runtime::geometry
