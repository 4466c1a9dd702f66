// POV-Ray's sphere { center, radius } in object space.
//
// Hits: part 0. uv (sphere_uv of the hit's normal) as POV-Ray's uv_mapping:
// u = the angle around +y from +x toward +z as a fraction of a turn,
// v = 0.5 + latitude / pi (0 at -y, 1 at +y). intersect() leaves uv at 0:
// an arc tangent and an arc sine per hit are paid only for the hit that is
// shaded (SphereModel::uv, at complete()). inside: closed ball. A radius
// <= 0 is an empty shape.
//
// Accuracy: the nearer root is the stable one of Ray Tracing Gems ch. 7,
// solved from an origin moved next to the sphere; s is good to a few ulps and
// the hit point lies on the sphere to a few ulps of max(radius, |center|),
// for radii from 1e-6 to 1e6 and origins 1e6 away alike.
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "runtime/geometry/ray3.hpp"

namespace hexant::runtime::geometry {

struct SphereGeometry {
    glm::dvec3 center{0.0};
    double radius = 1.0;
};

std::optional<SurfaceHit> intersect(const SphereGeometry& sphere, const Ray3& ray, double s_min,
                                    double s_max);
bool inside(const SphereGeometry& sphere, glm::dvec3 p);
glm::dvec2 sphere_uv(const glm::dvec3& unit_normal);
Box3 object_bounds(const SphereGeometry& sphere);
bool surface_may_meet(const SphereGeometry& sphere, const Box3& box);

}  // namespace hexant::runtime::geometry
