// POV-Ray's cone { base, base_radius, cap, cap_radius [open] } in object
// space: the truncated cone whose radius runs linearly from base_radius at
// base to cap_radius at cap (equal radii make a cylinder).
//
// Hits: part 0 the side, 1 the end cap at base, 2 the end cap at cap (a cap
// of radius 0 is absent); open: no end caps. Normals outward (on the side the
// gradient of distance-from-axis minus radius). uv as the cylinder: side u =
// angle around the axis in orthonormal_basis(axis) / turn, v = height / length;
// caps u = angle, v = distance from the axis / that end's radius. inside: the
// closed solid (also when open). Base == cap, a negative radius or both radii
// zero is an empty shape.
//
// Accuracy: as the cylinder; the quadratic's leading coefficient may vanish
// (a ray parallel to a generator line) or turn negative, which the stable
// root pair handles without special cases. Apex hits have a normal along the
// axis tilted by the slope.
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "runtime/geometry/ray3.hpp"

namespace hexant::runtime::geometry {

struct ConeGeometry {
    glm::dvec3 base{0.0};
    double base_radius = 1.0;
    glm::dvec3 cap{0.0, 1.0, 0.0};
    double cap_radius = 0.0;
    bool open = false;
};

std::optional<SurfaceHit> intersect(const ConeGeometry& cone, const Ray3& ray, double s_min,
                                    double s_max);
bool inside(const ConeGeometry& cone, glm::dvec3 p);
Box3 object_bounds(const ConeGeometry& cone);
bool surface_may_meet(const ConeGeometry& cone, const Box3& box);

}  // namespace hexant::runtime::geometry
