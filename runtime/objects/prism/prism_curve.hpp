// The prism's curved path (prism_geometry.hpp): every form but linear_sweep
// with linear_spline, on the outline's cubic segments, after POV-Ray 3.7's
// Prism (prism.cpp):
// - a linear sweep's side: the ray's line in x-z crosses the segment where
//   u_z (x(t) - o_x) - u_x (z(t) - o_z) = 0 (All_Intersections' cubic);
// - a conic sweep's side is the lines through the origin and <x(t), 1, z(t)>:
//   one meets the ray where that point lies in the plane of the ray and the
//   origin, (o x u) . <x(t), 1, z(t)> = 0 (POV-Ray's k1 x + k3 + k2 z = 0);
//   the distance along the ray is then the least-squares solution of
//   (o + k u) x L = 0 (POV-Ray divides by one component, which may be 0);
// - the caps: the ray at a height, inside the outline there (a conic sweep's
//   scaled by 1 / height, none at height 0);
// - inside (POV-Ray's in_curve and Inside): between the heights, and the
//   half-line from the point toward +x crosses the outline an odd number of
//   times (where z(t) = z and x(t) >= x; POV-Ray counts every root in
//   [0, 1], so a joint on the line counts twice; hexant counts changes of
//   side, see crossings in prism_curve.cpp), at x / y, z / y for a conic
//   sweep;
// - the normal (POV-Ray's Normal): <z'(t), 0, -x'(t)> for a linear sweep;
//   for a conic one <z', x' z - z' x, -x'> (the cross product of the two
//   tangents over y), turned outward by the inside rule (POV-Ray leaves it
//   as the segment's direction makes it).
// Roots by polynomial_roots on t in [0, 1] widened by 1e-9 (so a ray through
// a joint between segments is not lost to rounding).
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "runtime/objects/prism/prism_geometry.hpp"

namespace hexant::runtime::geometry {

// The segments POV-Ray makes of the points (none where it refuses or
// ignores them, or a point is not finite).
std::vector<PrismSegment> prism_segments(PrismSpline spline, std::span<const glm::dvec2> points);

std::optional<SurfaceHit> intersect_curved(const PrismGeometry& prism, const Ray3& ray,
                                           double s_min, double s_max);
bool inside_curved(const PrismGeometry& prism, glm::dvec3 p);
Box3 curved_bounds(const PrismGeometry& prism);
bool curved_surface_may_meet(const PrismGeometry& prism, const Box3& box);

}  // namespace hexant::runtime::geometry
