// A truncated cone of revolution between two points, with a radius at each
// end: the common body of POV-Ray's cylinder (equal radii) and cone. Used by
// cylinder.cpp and cone.cpp; see cone.hpp for the conventions.
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "runtime/geometry/ray3.hpp"

namespace hexant::runtime::geometry {

struct Frustum {
    glm::dvec3 base, cap;
    double base_radius, cap_radius;
    bool open;
};

std::optional<SurfaceHit> intersect_frustum(const Frustum& frustum, const Ray3& ray, double s_min,
                                            double s_max);
bool inside_frustum(const Frustum& frustum, glm::dvec3 p);
Box3 frustum_bounds(const Frustum& frustum);
bool frustum_may_meet(const Frustum& frustum, const Box3& box);

}  // namespace hexant::runtime::geometry
