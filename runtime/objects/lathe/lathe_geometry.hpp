// POV-Ray's lathe { [linear_spline | quadratic_spline | cubic_spline |
// bezier_spline] N, <P0>, ..., <PN-1> } in object space: a profile in the
// (r, y) plane, points given as <r, y>, turned about the y axis. Each spline
// segment is a cubic (A t^3 + B t^2 + C t + D, t in [0, 1]) made from the
// points exactly as POV-Ray 3.7's Lathe::Compute_Lathe does (lathe.cpp):
//   linear     N - 1 segments, P[i] to P[i+1];
//   quadratic  N - 2 segments from P[i], P[i+1], P[i+2], running from P[i+1]
//              to P[i+2] (P[0] only steers the first);
//   cubic      N - 3 segments (Catmull-Rom) from P[i] .. P[i+3], running from
//              P[i+1] to P[i+2] (the first and last points steer);
//   bezier     N / 4 segments, each of four points P[4i] .. P[4i+3].
// The surface at a profile point is the circle of radius |r(t)| (POV-Ray
// squares r in its equation).
//
// Hits: part = segment index; the normal is POV-Ray's (dy/dt along the
// radial direction, -dr/dt along y), turned outward by the inside rule; uv as
// POV-Ray's Lathe::UVCoord: u = the angle about y from +x toward +z over 2pi
// (0 on the axis), v = (segment + t) / segments. inside: POV-Ray's rule,
// the parity of the profile's crossings of the horizontal half-line from the
// point outward (roots of y(t) = y in [0, 1) with r(t) >= the point's
// radius; POV-Ray counts t = 1 too, which counts a shared vertex twice).
// Fewer than one segment, or non-finite points, is an empty shape.
//
// Accuracy: the ray (moved next to the lathe) and a segment give POV-Ray's
// polynomial in t of degree 2, 4 or 6 (the height eliminated through the
// ray's y), solved by polynomial_roots on [0, 1]; for nearly horizontal
// rays, whose roots come in pairs closer than the coefficients' rounding,
// the roots of y(t) = the ray's height seed too. Each root is then polished
// by Newton's method on the two equations (height and radius) in (k, t),
// which gives k (the distance along the ray) to a few ulps of the lathe's
// size whatever the ray's slope.
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "runtime/geometry/ray3.hpp"

namespace hexant::runtime::geometry {

enum class LatheSpline { linear, quadratic, cubic, bezier };

// One segment: x = the radius, y = the height, each a t^3 + b t^2 + c t + d.
struct LatheSegment {
    glm::dvec2 a{0.0}, b{0.0}, c{0.0}, d{0.0};
    // Bounds of |r(t)| and y(t) over [0, 1] (slightly widened: conservative).
    double r_lo = 0.0, r_hi = 0.0, y_lo = 0.0, y_hi = 0.0;

    glm::dvec2 at(double t) const { return ((a * t + b) * t + c) * t + d; }
    glm::dvec2 slope(double t) const { return (3.0 * a * t + 2.0 * b) * t + c; }
};

struct LatheGeometry {
    std::vector<LatheSegment> segments;
    double radius = 0.0;                  // the largest |r(t)|
    double height1 = 0.0, height2 = 0.0;  // the height range
};

// How many segments N points make (POV-Ray's rule; 0 when too few).
int lathe_segment_count(LatheSpline spline, std::size_t points);

// The segments' polynomials, exactly POV-Ray's formulas, for any number type
// (double, or Interval for bounds over time). P at(i) gives point i as a
// pair (x, y) of T.
template <class T>
struct LathePolynomial {
    T a[2], b[2], c[2], d[2];  // [0] radius, [1] height
};

template <class T, class At>
LathePolynomial<T> lathe_polynomial(LatheSpline spline, int segment, At&& at) {
    LathePolynomial<T> p;
    const int i = spline == LatheSpline::bezier ? 4 * segment : segment;
    for (int k = 0; k < 2; ++k) {
        switch (spline) {
            case LatheSpline::linear: {
                const T p0 = at(i, k), p1 = at(i + 1, k);
                p.a[k] = T(0.0);
                p.b[k] = T(0.0);
                p.c[k] = T(-1.0) * p0 + T(1.0) * p1;
                p.d[k] = T(1.0) * p0;
                break;
            }
            case LatheSpline::quadratic: {
                const T p0 = at(i, k), p1 = at(i + 1, k), p2 = at(i + 2, k);
                p.a[k] = T(0.0);
                p.b[k] = T(0.5) * p0 - T(1.0) * p1 + T(0.5) * p2;
                p.c[k] = T(-0.5) * p0 + T(0.5) * p2;
                p.d[k] = T(1.0) * p1;
                break;
            }
            case LatheSpline::cubic: {
                const T p0 = at(i, k), p1 = at(i + 1, k), p2 = at(i + 2, k), p3 = at(i + 3, k);
                p.a[k] = T(-0.5) * p0 + T(1.5) * p1 - T(1.5) * p2 + T(0.5) * p3;
                p.b[k] = p0 - T(2.5) * p1 + T(2.0) * p2 - T(0.5) * p3;
                p.c[k] = T(-0.5) * p0 + T(0.5) * p2;
                p.d[k] = p1;
                break;
            }
            case LatheSpline::bezier: {
                const T p0 = at(i, k), p1 = at(i + 1, k), p2 = at(i + 2, k), p3 = at(i + 3, k);
                p.a[k] = p3 - T(3.0) * p2 + T(3.0) * p1 - p0;
                p.b[k] = T(3.0) * p2 - T(6.0) * p1 + T(3.0) * p0;
                p.c[k] = T(3.0) * p1 - T(3.0) * p0;
                p.d[k] = p0;
                break;
            }
        }
    }
    return p;
}

// The hull over t in [0, 1] of a segment's component k (0 or 1): its
// Bernstein control points, for T = Interval (a cubic spline overshoots its
// points; its control hull does not).
template <class T>
T lathe_control_hull(const LathePolynomial<T>& p, int k) {
    const T third = T(1.0) / T(3.0);
    const T b0 = p.d[k];
    const T b1 = p.d[k] + p.c[k] * third;
    const T b2 = p.d[k] + (T(2.0) * p.c[k] + p.b[k]) * third;
    const T b3 = p.a[k] + p.b[k] + p.c[k] + p.d[k];
    return hull(hull(b0, b1), hull(b2, b3));
}

// The lathe from its spline and points (<r, y>); no segments when there are
// too few points or a point is not finite.
LatheGeometry make_lathe(LatheSpline spline, const std::vector<glm::dvec2>& points);

std::optional<SurfaceHit> intersect(const LatheGeometry& lathe, const Ray3& ray, double s_min,
                                    double s_max);
bool inside(const LatheGeometry& lathe, glm::dvec3 p);
Box3 object_bounds(const LatheGeometry& lathe);
bool surface_may_meet(const LatheGeometry& lathe, const Box3& box);

}  // namespace hexant::runtime::geometry
