// POV-Ray's prism { [linear_sweep | conic_sweep] [linear_spline |
// quadratic_spline | cubic_spline | bezier_spline] height1, height2, n,
// points [open] } in object space: outlines in the x-z plane (points given
// as <x, z>) filled by the even-odd rule, swept along y between the two
// heights: straight up (linear_sweep), or scaled by the height from the
// origin (conic_sweep: the outline's point <x, z> lies at <y x, y, y z>,
// POV-Ray's Prism::All_Intersections).
//
// Two paths:
// - linear_sweep with linear_spline works on the points directly, split into
//   closed outlines as for the polygon (outline.hpp);
// - every other form works on `segments`, the outline's cubic pieces as
//   POV-Ray's Compute_Prism makes them (prism_outline.hpp, make_prism);
//   the routines are in prism_curve.hpp.
//
// Hits: part 0 the cap at the lower height (normal -y), 1 the cap at the
// upper height (normal +y), 2 + i the side swept by edge or segment i
// (edges numbered in point-list order, closing edges after each outline's
// last point, edges of zero length skipped; segments in POV-Ray's order);
// open: no caps. Side normals are outward by the even-odd rule. uv (POV-Ray
// defines none for prisms): caps (x, z); sides u = the fraction along the
// edge from its first point (a segment's parameter), v = the fraction of
// the height from the lower cap. inside: the closed solid (also when open).
// Fewer than two distinct points, or no segments, is an empty shape.
//
// Accuracy: the side faces of the linear path are found in 2D by which side
// of the ray's line each vertex lies (difference_of_products): both faces at
// a shared vertex decide that vertex the same way, so rays do not slip
// through the seams. s to a few ulps, from an origin moved next to the
// prism. The curved path: prism_curve.hpp.
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "runtime/geometry/ray3.hpp"
#include "runtime/objects/prism/prism_outline.hpp"

namespace hexant::runtime::geometry {

enum class PrismSweep { linear, conic };

// One segment of the outline: <x, z>(t) = a t^3 + b t^2 + c t + d, t in
// [0, 1]; lo and hi bound it over [0, 1] (slightly widened: conservative);
// start and end are its ends as the points give them (exactly the same
// numbers in the two segments that share an end, which the polynomial at 1
// is not).
struct PrismSegment {
    glm::dvec2 a{0.0}, b{0.0}, c{0.0}, d{0.0};
    glm::dvec2 lo{0.0}, hi{0.0};
    glm::dvec2 start{0.0}, end{0.0};

    glm::dvec2 at(double t) const { return ((a * t + b) * t + c) * t + d; }
    glm::dvec2 slope(double t) const { return (3.0 * a * t + 2.0 * b) * t + c; }
};

struct PrismGeometry {
    double height1 = 0.0, height2 = 1.0;
    std::vector<glm::dvec2> points;  // <x, z>
    bool open = false;
    PrismSpline spline = PrismSpline::linear;
    PrismSweep sweep = PrismSweep::linear;
    // The curved path's segments (make_prism); unused by the linear path.
    std::vector<PrismSegment> segments;
};

// Whether the prism takes the curved path (every form but linear_sweep with
// linear_spline).
inline bool curved(const PrismGeometry& prism) {
    return prism.spline != PrismSpline::linear || prism.sweep != PrismSweep::linear;
}

// The prism of a form, heights and points; the curved path's segments made
// as POV-Ray does (none when POV-Ray refuses or ignores the prism, or a
// number is not finite).
PrismGeometry make_prism(PrismSpline spline, PrismSweep sweep, double height1, double height2,
                         std::vector<glm::dvec2> points, bool open);

std::optional<SurfaceHit> intersect(const PrismGeometry& prism, const Ray3& ray, double s_min,
                                    double s_max);
bool inside(const PrismGeometry& prism, glm::dvec3 p);
Box3 object_bounds(const PrismGeometry& prism);
bool surface_may_meet(const PrismGeometry& prism, const Box3& box);

}  // namespace hexant::runtime::geometry
