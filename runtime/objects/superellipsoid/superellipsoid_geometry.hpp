// POV-Ray's superellipsoid { <e, n> } in object space, as POV-Ray 3.7
// evaluates it (super.cpp): with the powers Px = 2/e and Pz = 2/n
// (Parse_Superellipsoid),
//   g(a, b, P) = max(a, b) (1 + (min/max)^P)^(1/P)      (evaluate_g)
//   F(p) = g(g(|x|, |y|, Px), |z|, Pz) - 1               (evaluate_superellipsoid)
// the solid is F <= 0, the surface F = 0. g is positively homogeneous of
// degree 1 and increasing in both arguments, so F + 1 >= max(|x|, |y|, |z|)
// (the surface lies in the unit box) and the range of F over any box is
// given exactly by its corners nearest to and farthest from the origin
// (after folding into the positive octant): the interval extension the
// root search and surface_may_meet use.
//
// Exponents: e and n must be finite and >= 0; e = 0 (or n = 0) gives
// POV-Ray's infinite power, the flat faces of the cube. A negative or
// non-finite exponent is an empty shape (POV-Ray computes something there
// that is clipped by its bounding box; see superellipsoid_geometry.cpp).
//
// Hits: part 0; uv (0, 0) (POV-Ray has no uv mapping for it); the normal
// is the gradient of F (the same direction as POV-Ray's
// Superellipsoid::Normal, computed through logarithms so that no
// exponent overflows it). inside: F < 1e-10 (POV-Ray's EPSILON).
//
// Root search (in place of POV-Ray's sampling at the planes x = ±y, ...,
// z = 0 and its secant checks, which can step over thin hits): the ray,
// moved next to the box, is clipped to the unit box and cut in halves,
// front first; a piece whose interval of F excludes 0 is dropped; a piece
// shorter than 1e-7 with a sign change is refined by bisection to adjacent
// doubles; one without, whose F comes within its rounding (1e-12) of 0, is
// a touch (a tangent ray) and a hit. No crossing of the surface wider than
// 1e-7 of the box is missed. A ray that runs within the surface for a
// stretch may be: after 2^16 pieces (an ordinary ray needs a few hundred, a
// tangent one to a flat face up to about 22,000) the search looks only for sign changes at
// the ends of the pieces it holds.
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "runtime/geometry/ray3.hpp"

namespace hexant::runtime::geometry {

struct SuperellipsoidGeometry {
    double e = 2.0, n = 2.0;
    double px = 1.0, pz = 1.0;  // POV-Ray's Power[X] = 2/e, Power[Z] = 2/n
    bool valid = false;
};

SuperellipsoidGeometry make_superellipsoid(double e, double n);

// POV-Ray's evaluate_superellipsoid: F(p) (>= -1; may be +Inf far out for
// huge exponents, never NaN for a valid shape and finite p).
double superellipsoid_function(const SuperellipsoidGeometry& g, const glm::dvec3& p);
// The unit outward gradient direction of F at p ((0, 1, 0) at the origin).
glm::dvec3 superellipsoid_normal(const SuperellipsoidGeometry& g, const glm::dvec3& p);
// The solid's volume, 2 n e B(n/2 + 1, n) B(e/2, e/2) (Jaklic, Leonardis,
// Solina, "Segmentation and Recovery of Superquadrics", 2000, 2.6);
// -1 when invalid.
double superellipsoid_volume(const SuperellipsoidGeometry& g);

std::optional<SurfaceHit> intersect(const SuperellipsoidGeometry& g, const Ray3& ray, double s_min,
                                    double s_max);
bool inside(const SuperellipsoidGeometry& g, glm::dvec3 p);
Box3 object_bounds(const SuperellipsoidGeometry& g);
bool surface_may_meet(const SuperellipsoidGeometry& g, const Box3& box);

}  // namespace hexant::runtime::geometry
