// POV-Ray's smooth_triangle { p1, n1, p2, n2, p3, n3 } in object space.
//
// The surface is the flat triangle; only the shading normal differs. Hits:
// part 0; normal = normalize(cross(p2 - p1, p3 - p1)); shading_normal = the
// barycentric blend of the unit vertex normals, normalised (the geometric
// normal where the blend vanishes or a vertex normal is zero); uv = (b2, b3)
// as for the triangle. inside: always false (flat).
//
// Accuracy: as the triangle (the same watertight test).
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "runtime/geometry/ray3.hpp"

namespace hexant::runtime::geometry {

struct SmoothTriangleGeometry {
    glm::dvec3 p1{0.0}, n1{0.0, 0.0, 1.0};
    glm::dvec3 p2{1.0, 0.0, 0.0}, n2{0.0, 0.0, 1.0};
    glm::dvec3 p3{0.0, 1.0, 0.0}, n3{0.0, 0.0, 1.0};
};

std::optional<SurfaceHit> intersect(const SmoothTriangleGeometry& triangle, const Ray3& ray,
                                    double s_min, double s_max);
bool inside(const SmoothTriangleGeometry& triangle, glm::dvec3 p);
Box3 object_bounds(const SmoothTriangleGeometry& triangle);
bool surface_may_meet(const SmoothTriangleGeometry& triangle, const Box3& box);

}  // namespace hexant::runtime::geometry
