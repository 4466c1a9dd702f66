// POV-Ray's disc { center, normal, radius [, hole_radius] } in object space:
// the points of the plane through center perpendicular to normal whose
// distance from center lies in [hole_radius, radius] (closed).
//
// Hits: part 0; normal = normal / |normal| whichever side the ray comes from;
// uv: u = the angle around the normal in orthonormal_basis(normal) as a
// fraction of a turn, v = distance from center / radius. inside: always false
// (flat). A zero normal or radius <= 0 is an empty shape.
//
// Accuracy: solved from an origin moved next to the disc; s to a few ulps,
// the hit point on the disc's plane to ulps of max(radius, |center|). A ray
// parallel to the plane has no hit (no division by zero).
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "runtime/geometry/local_ray.hpp"
#include "runtime/geometry/ray3.hpp"

namespace hexant::runtime::geometry {

struct DiscGeometry {
    glm::dvec3 center{0.0};
    glm::dvec3 normal{0.0, 1.0, 0.0};
    double radius = 1.0;
    double hole_radius = 0.0;
};

std::optional<SurfaceHit> intersect(const DiscGeometry& disc, const Ray3& ray, double s_min,
                                    double s_max);
bool inside(const DiscGeometry& disc, glm::dvec3 p);
Box3 object_bounds(const DiscGeometry& disc);
bool surface_may_meet(const DiscGeometry& disc, const Box3& box);

// Where a local ray crosses a disc (unit normal), shared with the end caps of
// cylinders and cones: the local distance t and the vector from the centre to
// the hit point within the plane, if that point lies on the disc.
struct DiscCrossing {
    double t;
    glm::dvec3 radial;
};
std::optional<DiscCrossing> cross_disc(const LocalRay& ray, const glm::dvec3& center,
                                       const glm::dvec3& unit_normal, double radius,
                                       double hole_radius);
// The may-meet test of such a disc (unit normal).
bool disc_may_meet(const glm::dvec3& center, const glm::dvec3& unit_normal, double radius,
                   double hole_radius, const Box3& box);

}  // namespace hexant::runtime::geometry
