// A polynomial surface at one instant, in object space (poly.hpp): p(x, y,
// z) = 0, solid where p < 0.
//
// Hits: the ray is restated near the object's origin (local_ray: polys are
// written about it), p along it becomes a polynomial in the distance t by
// expanding each term's powers of (o + t u), and its real roots in the
// searched range come from polynomial_roots (signs by compensated Horner:
// no root is reported where rounding cannot tell the sign). Part 0; the
// normal is p's gradient, unit, and (1, 0, 0) where it vanishes (a
// singular point); uv (0, 0). inside: p < 0, or p = 0 (on the surface, as
// POV-Ray's tolerance takes it). No object_bounds: the surface is unbounded.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "runtime/geometry/ray3.hpp"

namespace hexant::runtime::geometry {

struct PolyGeometry {
    int order = 2;
    // poly_term_count(order) coefficients in POV-Ray's order (poly_terms).
    std::vector<double> coefficients;
};

// The powers (i, j, k) of x^i y^j z^k of each term of a polynomial of
// `order` (1 to kMaxPolynomialDegree), in POV-Ray's order: one table per
// order, made once.
const std::vector<std::array<int, 3>>& poly_terms(int order);

std::optional<SurfaceHit> intersect(const PolyGeometry& g, const Ray3& ray, double s_min,
                                    double s_max);
bool inside(const PolyGeometry& g, glm::dvec3 p);
bool surface_may_meet(const PolyGeometry& g, const Box3& box);
// p and its gradient at a point.
double evaluate(const PolyGeometry& g, const glm::dvec3& p);
glm::dvec3 gradient(const PolyGeometry& g, const glm::dvec3& p);

}  // namespace hexant::runtime::geometry
