// POV-Ray's plane { normal, distance }: the points p with dot(p, n) = distance
// for n = normal / |normal| (POV-Ray normalises the normal, not the distance).
//
// Hits: part 0, normal n whichever side the ray comes from; uv = the hit
// point's coordinates along the two unit axes orthonormal_basis(n) gives (a
// plane has no uv_mapping in POV-Ray). inside: dot(p, n) <= distance, the side
// the normal points away from. A zero normal is an empty shape. No
// object_bounds: the plane is unbounded.
//
// Accuracy: s from one division, so a few ulps; a ray parallel to the plane
// (dot(direction, n) == 0) has no hit, and a nearly parallel one a huge s
// that fails any finite s_max, never an Inf or NaN.
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "runtime/geometry/ray3.hpp"

namespace hexant::runtime::geometry {

struct PlaneGeometry {
    glm::dvec3 normal{0.0, 1.0, 0.0};
    double distance = 0.0;
};

std::optional<SurfaceHit> intersect(const PlaneGeometry& plane, const Ray3& ray, double s_min,
                                    double s_max);
bool inside(const PlaneGeometry& plane, glm::dvec3 p);
bool surface_may_meet(const PlaneGeometry& plane, const Box3& box);

}  // namespace hexant::runtime::geometry
