// POV-Ray's triangle { p1, p2, p3 } in object space.
//
// Hits: part 0; normal = normalize(cross(p2 - p1, p3 - p1)), whichever side
// the ray comes from; uv = the barycentric weights (b2, b3) of p2 and p3, so
// point = p1 + u (p2 - p1) + v (p3 - p1). inside: always false (flat).
// A triangle of zero area is an empty shape.
//
// Accuracy: Woop, Benthin and Wald's watertight test ("Watertight Ray/Triangle
// Intersection", JCGT 2013) in double, its 2D edge functions formed by
// difference_of_products so that their signs are exact for the sheared vertex
// coordinates: a ray through a shared edge or vertex of two triangles hits at
// least one of them, never slips between. s is good to a few ulps; the hit
// point is formed from the barycentric weights (on the triangle's plane to
// ulps of the vertices, however far the origin).
#pragma once

#include <limits>
#include <optional>

#include <glm/glm.hpp>

#include "runtime/geometry/ray3.hpp"

namespace hexant::runtime::geometry {

struct TriangleGeometry {
    glm::dvec3 p1{0.0}, p2{1.0, 0.0, 0.0}, p3{0.0, 1.0, 0.0};
};

std::optional<SurfaceHit> intersect(const TriangleGeometry& triangle, const Ray3& ray, double s_min,
                                    double s_max);
bool inside(const TriangleGeometry& triangle, glm::dvec3 p);
Box3 object_bounds(const TriangleGeometry& triangle);
bool surface_may_meet(const TriangleGeometry& triangle, const Box3& box);

// The watertight test itself, shared with the smooth triangle: the ray's
// parameter and the barycentric weights of p1, p2, p3 (summing to 1).
struct BarycentricHit {
    double s;
    double b1, b2, b3;
    // A bound on s's error where it is known (s_min >= 0, where the sign
    // of s is checked), else infinity.
    double s_error = std::numeric_limits<double>::infinity();
};
std::optional<BarycentricHit> intersect_barycentric(const glm::dvec3& p1, const glm::dvec3& p2,
                                                    const glm::dvec3& p3, const Ray3& ray,
                                                    double s_min, double s_max);
// The error bound of the point b1 p1 + b2 p2 + b3 p3 formed from a hit's
// weights: gamma(7) of the summed magnitudes per coordinate (pbrt-v4,
// Triangle::InteractionFromIntersection: the weights' own rounding and the
// three products and two sums).
inline glm::dvec3 barycentric_error(const BarycentricHit& hit, const glm::dvec3& p1,
                                    const glm::dvec3& p2, const glm::dvec3& p3) {
    return rounding_gamma(7) *
           (glm::abs(hit.b1 * p1) + glm::abs(hit.b2 * p2) + glm::abs(hit.b3 * p3));
}
// Sets out.point and out.error: the point from the weights
// (barycentric_error's bound), or, where s's error is known and the ray
// gives the nearer point, origin + s direction, as POV-Ray forms it (a floor
// whose vertices are at 1e15 seen from a few units: the weights times the
// vertices round by a part of a unit, the ray's point by ulps of the origin).
void place_barycentric_hit(const BarycentricHit& hit, const glm::dvec3& p1, const glm::dvec3& p2,
                           const glm::dvec3& p3, const Ray3& ray, SurfaceHit& out);
// Separating-axis test (Akenine-Moller 2001) on the box widened by rounding.
bool triangle_may_meet(const glm::dvec3& p1, const glm::dvec3& p2, const glm::dvec3& p3,
                       const Box3& box);

}  // namespace hexant::runtime::geometry
