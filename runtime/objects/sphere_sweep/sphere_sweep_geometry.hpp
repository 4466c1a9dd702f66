// POV-Ray's sphere_sweep { linear_spline | b_spline | cubic_spline  N,
// <C1>, R1, ..., <CN>, RN } in object space: the union of every sphere
// whose centre and radius run along a spline. Each segment is a cubic in
// its parameter u in [0, 1] (centre and radius alike), made from the
// modelling spheres exactly as POV-Ray 3.7's SphereSweep::Compute does
// (sphsweep.cpp):
//   linear_spline  N - 1 segments, sphere i to sphere i + 1 (degree 1);
//   b_spline       N - 3 segments, segment i from spheres i .. i + 3 by the
//                  uniform cubic B-spline matrix (it passes near, not
//                  through, its spheres: segment i runs from
//                  (S[i] + 4 S[i+1] + S[i+2]) / 6 to the same of i + 1);
//   cubic_spline   N - 3 segments, Catmull-Rom from spheres i .. i + 3,
//                  running from sphere i + 1 to sphere i + 2 (the first and
//                  the last sphere only steer).
// POV-Ray squares the radius in every equation, so a negative radius is the
// positive one (|r(u)|). The shape is the union of the balls of radius
// |r(u)| about c(u) for u in [0, 1] over all segments: POV-Ray's spheres at
// the segments' ends plus each segment's envelope (for linear segments the
// cone frusta tangent to the end spheres).
//
// Hits: part = segment index; the normal is the outward normal of the
// sphere the hit lies on (that of the envelope where it touches it); uv =
// ((segment + u) / segments, 0) with u the hit sphere's parameter (POV-Ray
// gives sphere sweeps no uv mapping). inside: within some sphere of the
// union (POV-Ray 3.7 tests only for a root of |p - c(u)|^2 - r(u)^2 in
// [0, 1], which misses points inside every sphere of a segment; hexant takes
// the union as the documentation describes it). POV-Ray's `tolerance` (its
// depth below which hits are dropped) is not used: hexant starts secondary
// rays off the surface by the hit's error bound instead.
//
// Method: along the ray x(k) = o + k d (d unit), the sphere at u holds the
// stretch [m(u) - sqrt(D(u)), m(u) + sqrt(D(u))] where m = d.(c - o) and
// D = r^2 - |perp(c - o)|^2 (perp: the part across d). Over each connected
// range of u where D >= 0 those stretches form one interval, from the least
// lower end to the greatest upper end; both extremes are at u = 0, u = 1 or
// critical points, the roots of 4 m'^2 D - D'^2 (degree 10 for a cubic
// segment, the envelope condition), found with polynomial_roots. The ends of
// the merged intervals are the surface; each is computed from one sphere
// directly, which makes it insensitive (to second order) to the error in
// the root u. Everything is computed in a frame scaled by a power of two to
// the sweep's size, so no number depends on the scene's scale.
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "runtime/geometry/ray3.hpp"

namespace hexant::runtime::geometry {

enum class SweepSpline { linear, b_spline, cubic };

// One segment: centre (xyz) and radius (w), each coef[0] + coef[1] u +
// coef[2] u^2 + coef[3] u^3.
struct SweepSegment {
    glm::dvec4 coef[4] = {glm::dvec4(0.0), glm::dvec4(0.0), glm::dvec4(0.0), glm::dvec4(0.0)};
    Box3 box{glm::dvec3(0.0), glm::dvec3(0.0)};  // holds every ball of the segment (conservative)

    glm::dvec4 at(double u) const { return ((coef[3] * u + coef[2]) * u + coef[1]) * u + coef[0]; }
    glm::dvec4 slope(double u) const { return (3.0 * coef[3] * u + 2.0 * coef[2]) * u + coef[1]; }
};

struct SphereSweepGeometry {
    SweepSpline spline = SweepSpline::linear;
    // In the scaled frame: p' = (p - origin) * inverse_scale, each segment
    // within about [-1, 1]^3.
    std::vector<SweepSegment> segments;
    glm::dvec3 origin{0.0};
    double scale = 1.0, inverse_scale = 1.0;        // powers of two
    Box3 bounds{glm::dvec3(0.0), glm::dvec3(0.0)};  // in object space
    double size = 0.0;                              // the bounds' half diagonal
};

// How many segments N spheres make (POV-Ray's rule; 0 when too few).
int sphere_sweep_segment_count(SweepSpline spline, std::size_t spheres);

// A segment's coefficients from its spheres, POV-Ray's matrices, for any
// number type (double, or Interval for bounds over time). at(j, k) gives
// component k (0..2 the centre, 3 the radius) of sphere j; out[p][k] is the
// coefficient of u^p.
template <class T, class At>
void sphere_sweep_polynomial(SweepSpline spline, int segment, At&& at, T out[4][4]) {
    const int i = segment;
    for (int k = 0; k < 4; ++k) {
        switch (spline) {
            case SweepSpline::linear: {
                const T p0 = at(i, k), p1 = at(i + 1, k);
                out[0][k] = p0;
                out[1][k] = p1 - p0;
                out[2][k] = T(0.0);
                out[3][k] = T(0.0);
                break;
            }
            case SweepSpline::b_spline: {
                const T p0 = at(i, k), p1 = at(i + 1, k), p2 = at(i + 2, k), p3 = at(i + 3, k);
                out[0][k] = (p0 + T(4.0) * p1 + p2) / T(6.0);
                out[1][k] = (p2 - p0) * T(0.5);
                out[2][k] = (p0 - T(2.0) * p1 + p2) * T(0.5);
                out[3][k] = (T(3.0) * (p1 - p2) + p3 - p0) / T(6.0);
                break;
            }
            case SweepSpline::cubic: {
                const T p0 = at(i, k), p1 = at(i + 1, k), p2 = at(i + 2, k), p3 = at(i + 3, k);
                out[0][k] = p1;
                out[1][k] = (p2 - p0) * T(0.5);
                out[2][k] = p0 - T(2.5) * p1 + T(2.0) * p2 - T(0.5) * p3;
                out[3][k] = (T(3.0) * (p1 - p2) + p3 - p0) * T(0.5);
                break;
            }
        }
    }
}

// The sweep from its spline and spheres; no segments (an empty shape) when
// there are too few spheres or a number is not finite.
SphereSweepGeometry make_sphere_sweep(SweepSpline spline, const std::vector<glm::dvec3>& centres,
                                      const std::vector<double>& radii);

std::optional<SurfaceHit> intersect(const SphereSweepGeometry& g, const Ray3& ray, double s_min,
                                    double s_max);
bool inside(const SphereSweepGeometry& g, glm::dvec3 p);
Box3 object_bounds(const SphereSweepGeometry& g);
bool surface_may_meet(const SphereSweepGeometry& g, const Box3& box);

}  // namespace hexant::runtime::geometry
