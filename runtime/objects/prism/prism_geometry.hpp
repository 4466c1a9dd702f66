// POV-Ray's prism { linear_sweep linear_spline height1, height2, n, points
// [open] } in object space: outlines in the x-z plane (points given as
// <x, z>, split into closed outlines as for the polygon, see outline.hpp,
// filled by the even-odd rule) swept along y between the two heights.
//
// Hits: part 0 the cap at the lower height (normal -y), 1 the cap at the
// upper height (normal +y), 2 + i the side face swept by edge i (edges
// numbered in point-list order, closing edges after each outline's last
// point, edges of zero length skipped); open: no caps. Side normals are
// horizontal, outward by the even-odd rule. uv (POV-Ray defines none for
// prisms): caps (x, z); sides u = the fraction along the edge from its first
// point, v = the fraction of the height from the lower cap. inside: the
// closed solid (also when open).
// Fewer than two distinct points is an empty shape.
//
// Accuracy: the side faces are found in 2D by which side of the ray's line
// each vertex lies (difference_of_products): both faces at a shared vertex
// decide that vertex the same way, so rays do not slip through the seams. s
// to a few ulps, from an origin moved next to the prism.
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "runtime/geometry/ray3.hpp"

namespace hexant::runtime::geometry {

struct PrismGeometry {
    double height1 = 0.0, height2 = 1.0;
    std::vector<glm::dvec2> points;  // <x, z>
    bool open = false;
};

std::optional<SurfaceHit> intersect(const PrismGeometry& prism, const Ray3& ray, double s_min,
                                    double s_max);
bool inside(const PrismGeometry& prism, glm::dvec3 p);
Box3 object_bounds(const PrismGeometry& prism);
bool surface_may_meet(const PrismGeometry& prism, const Box3& box);

}  // namespace hexant::runtime::geometry
