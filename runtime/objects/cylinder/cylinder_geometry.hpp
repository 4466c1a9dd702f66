// POV-Ray's cylinder { base, cap, radius [open] } in object space.
//
// Hits: part 0 the side, 1 the end cap at base (normal toward base, away
// from cap), 2 the end cap at cap; open: no end caps. Normals outward. uv
// (POV-Ray 3.7 has no uv_mapping here): on the side u = the angle around the
// axis in orthonormal_basis(axis) as a fraction of a turn, v = the height
// from base as a fraction of the length; on a cap u = the same angle, v =
// distance from the axis / radius. inside: the closed solid (also when open,
// as POV-Ray). Base == cap or radius <= 0 is an empty shape.
//
// Accuracy: the side quadratic with the axis projected out and the
// discriminant of Ray Tracing Gems ch. 7 (see frustum.cpp), solved from an
// origin moved next to the cylinder: s to a few ulps, hit points on the
// surface to ulps of max(radius, length, |base|), for radii 1e-6 to 1e6 and
// origins 1e6 away; a ray parallel to the axis hits only the caps.
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "runtime/geometry/ray3.hpp"

namespace hexant::runtime::geometry {

struct CylinderGeometry {
    glm::dvec3 base{0.0}, cap{0.0, 1.0, 0.0};
    double radius = 1.0;
    bool open = false;
};

std::optional<SurfaceHit> intersect(const CylinderGeometry& cylinder, const Ray3& ray, double s_min,
                                    double s_max);
bool inside(const CylinderGeometry& cylinder, glm::dvec3 p);
Box3 object_bounds(const CylinderGeometry& cylinder);
bool surface_may_meet(const CylinderGeometry& cylinder, const Box3& box);

}  // namespace hexant::runtime::geometry
