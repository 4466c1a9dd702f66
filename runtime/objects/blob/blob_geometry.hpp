// POV-Ray 3.7's blob in object space (blob.cpp): a field summed over
// components, its surface where the field equals the threshold.
//
// A component of strength s and radius R adds s (1 - d^2 / R^2)^2 where
// d < R, else nothing (Make_Blob: c0 = s / R^4, c1 = -2 s / R^2, c2 = s;
// density = c0 d^4 + c1 d^2 + c2). For a sphere d is the distance to its
// centre; for a cylinder, the distance to its segment from base to apex:
// POV-Ray's cylinder component (radial distance where 0 <= z <= length)
// with its two hemispherical caps (distance to the base for z <= 0, to the
// apex for z >= length). Inside: field > threshold - 1e-6 (INSIDE_TOLERANCE).
//
// Intersection, as All_Intersections: the ray is split where a piece's
// influence begins or ends (a sphere's ball; a cylinder's body, and each
// cap's half ball), so that on each interval the set of pieces is constant
// and field - threshold is one quartic in the ray parameter, whose roots
// polynomial_roots finds (in place of POV-Ray's Solve_Polynomial). Only
// the influence intervals are searched (POV-Ray's rule: where no component
// reaches, the field is 0 and no surface is found, whatever the threshold).
//
// Hits: normal = -grad(field) normalized (POV-Ray's Blob::Normal: sum of
// 2 s / R^2 (1 - d^2 / R^2) (p - closest point), or <1, 0, 0> where that is
// zero); shading_normal = normal; uv = (0, 0) (POV-Ray 3.7 gives blobs no
// uv mapping); part = 0.
//
// A component may carry its own transforms (POV-Ray's Element->Trans, which
// turns a scaled sphere into its ellipsoid piece): its field at p is its
// untransformed field at to_component p, so the ray is taken into its space
// for its pieces and the gradient back out by to_component's transpose.
//
// Not here (the record's work): the components' textures, the `sturm` and
// `hierarchy` flags, the old `component` syntax (the same sphere: strength,
// radius, centre).
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "runtime/geometry/ray3.hpp"

namespace hexant::runtime::geometry {

struct BlobComponent {
    enum class Kind { sphere, cylinder };
    Kind kind = Kind::sphere;
    glm::dvec3 a{0.0};  // centre, or the cylinder's base
    glm::dvec3 b{0.0};  // the cylinder's apex (unused for a sphere)
    double radius = 1.0;
    double strength = 1.0;
    // Its own transforms: component space to blob space, and back.
    bool transformed = false;
    glm::dmat4 to_blob{1.0}, to_component{1.0};
};

struct BlobGeometry {
    double threshold = 1.0;
    std::vector<BlobComponent> components;
};

// The field at p (POV-Ray's calculate_field_value).
double blob_field(const BlobGeometry& blob, const glm::dvec3& p);
// -grad(field) at p, not normalized.
glm::dvec3 blob_field_descent(const BlobGeometry& blob, const glm::dvec3& p);
// |field| of each component at p, in order (POV-Ray's
// determine_element_texture weighs component textures by it).
void blob_component_densities(const BlobGeometry& blob, const glm::dvec3& p,
                              std::vector<double>& out);

std::optional<SurfaceHit> intersect(const BlobGeometry& blob, const Ray3& ray, double s_min,
                                    double s_max);
bool inside(const BlobGeometry& blob, glm::dvec3 p);
// The union of the components' reaches (balls and capsules): the surface,
// where the field is the threshold, lies within it unless the threshold is
// not positive.
Box3 object_bounds(const BlobGeometry& blob);
// By bounds on each component's field over the box (its least and greatest
// distance from the box): "no" only where field - threshold cannot change
// sign in the box.
bool surface_may_meet(const BlobGeometry& blob, const Box3& box);

}  // namespace hexant::runtime::geometry
