// POV-Ray's box { corner1, corner2 } in object space (corners in any order).
//
// Hits: part = 2 * axis + (1 if the face at the larger coordinate else 0):
// 0 -x, 1 +x, 2 -y, 3 +y, 4 -z, 5 +z (POV-Ray's X0, X1, Y0, Y1, Z0, Z1).
// uv as POV-Ray's uv_mapping (the cube unfolded into a 4 x 3 cross).
// inside: the closed box. A box with lo > hi in no axis but zero thickness
// still has its faces (a flat box is hit on its two coincident faces).
//
// Accuracy: the slab test in the ray's moved frame; a zero direction
// component is handled apart (no 0 * inf), the hit point's face coordinate is
// the face's own value exactly and s is good to a few ulps.
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "runtime/geometry/ray3.hpp"

namespace hexant::runtime::geometry {

struct BoxGeometry {
    glm::dvec3 corner1{-1.0}, corner2{1.0};
};

std::optional<SurfaceHit> intersect(const BoxGeometry& box, const Ray3& ray, double s_min,
                                    double s_max);
bool inside(const BoxGeometry& box, glm::dvec3 p);
Box3 object_bounds(const BoxGeometry& box);
bool surface_may_meet(const BoxGeometry& box, const Box3& region);

}  // namespace hexant::runtime::geometry
