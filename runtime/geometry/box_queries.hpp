// Questions about a Box3 that the surface_may_meet tests ask: overlap,
// distances from a point, the box around a disc, and the rounding margin.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/glm.hpp>

#include "runtime/geometry/ray3.hpp"
#include "runtime/geometry/stable_arithmetic.hpp"

namespace hexant::runtime::geometry {

// surface_may_meet must never say "no" for a box that touches the surface.
// Both the box (often a single sampled or computed point) and our own test
// carry rounding of a few ulps of the largest coordinate involved, so every
// test is made on a box widened by this many ulps of that magnitude: relative,
// never a scene-scale constant, and 1e-14 of the size, so it costs nothing.
inline constexpr double kMeetSlackUlps = 64.0;

inline double meet_slack(const Box3& box, double shape_magnitude) {
    const double m = std::max({max_abs(box.lo), max_abs(box.hi), std::fabs(shape_magnitude)});
    return kMeetSlackUlps * kEpsilon * m;
}

inline Box3 widened(const Box3& box, double amount) {
    return {box.lo - amount, box.hi + amount};
}

// Whether the closed boxes share a point. Written as "not separated" so that
// a NaN anywhere answers yes: a may-meet test must err toward yes.
inline bool overlaps(const Box3& a, const Box3& b) {
    return !(a.lo.x > b.hi.x || b.lo.x > a.hi.x || a.lo.y > b.hi.y || b.lo.y > a.hi.y ||
             a.lo.z > b.hi.z || b.lo.z > a.hi.z);
}

inline bool contains(const Box3& box, const glm::dvec3& p) {
    return box.lo.x <= p.x && p.x <= box.hi.x && box.lo.y <= p.y && p.y <= box.hi.y &&
           box.lo.z <= p.z && p.z <= box.hi.z;
}

inline glm::dvec3 centre(const Box3& box) {
    return 0.5 * box.lo + 0.5 * box.hi;
}

// Half the diagonal: the radius of the smallest ball around the box.
inline double half_diagonal(const Box3& box) {
    return 0.5 * safe_length(box.hi - box.lo);
}

inline std::array<glm::dvec3, 8> corners(const Box3& box) {
    std::array<glm::dvec3, 8> c;
    for (int i = 0; i < 8; ++i) {
        c[i] = {(i & 1) ? box.hi.x : box.lo.x, (i & 2) ? box.hi.y : box.lo.y,
                (i & 4) ? box.hi.z : box.lo.z};
    }
    return c;
}

// The distance from p to the nearest point of the box (0 inside).
inline double min_distance(const Box3& box, const glm::dvec3& p) {
    const glm::dvec3 nearest = glm::clamp(p, box.lo, box.hi);
    return safe_length(p - nearest);
}

// The distance from p to the farthest point of the box (a corner).
inline double max_distance(const Box3& box, const glm::dvec3& p) {
    const glm::dvec3 far{std::max(std::fabs(p.x - box.lo.x), std::fabs(p.x - box.hi.x)),
                         std::max(std::fabs(p.y - box.lo.y), std::fabs(p.y - box.hi.y)),
                         std::max(std::fabs(p.z - box.lo.z), std::fabs(p.z - box.hi.z))};
    return safe_length(far);
}

// The tight box around a disc of the given radius about a unit normal: along
// axis i the disc reaches radius * sqrt(1 - n_i^2).
inline Box3 disc_bounds(const glm::dvec3& centre_point, const glm::dvec3& unit_normal,
                        double radius) {
    const glm::dvec3 n2 = unit_normal * unit_normal;
    const glm::dvec3 reach =
        std::fabs(radius) * glm::sqrt(glm::max(glm::dvec3(1.0) - n2, glm::dvec3(0.0)));
    return {centre_point - reach, centre_point + reach};
}

inline Box3 hull(const Box3& a, const Box3& b) {
    return {glm::min(a.lo, b.lo), glm::max(a.hi, b.hi)};
}

// True when the box (widened by slack) reaches both sides of the plane
// dot(p, n) = offset, n of unit length: the signed distances of its corners
// straddle zero. Exact in the minimum and maximum (one corner each).
inline bool straddles_plane(const Box3& box, const glm::dvec3& n, double offset, double slack) {
    const glm::dvec3 c = centre(box);
    const glm::dvec3 half = 0.5 * (box.hi - box.lo);
    const double mid = glm::dot(c, n) - offset;
    const double reach =
        glm::dot(half, glm::abs(n)) + slack * (1.0 + glm::dot(glm::abs(n), glm::dvec3(1.0)));
    return !(mid - reach > 0.0) && !(mid + reach < 0.0);
}

}  // namespace hexant::runtime::geometry
