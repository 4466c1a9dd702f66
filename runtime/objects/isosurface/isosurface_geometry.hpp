// An isosurface at one instant, in object space: the solid
//   S = C ∩ { p : F(p, t) - T <= 0 }
// of a user function F (runtime/time/user_function.hpp) inside its
// container C, a box or a sphere; its surface is F = T inside C and, unless
// `open`, the walls of C where F < T (POV-Ray's IsoSurface, isosurf.cpp).
//
// Root search, in place of POV-Ray's sampling by max_gradient (which
// misses the surface where the gradient is larger than the user said):
// the ray is clipped to C and cut in halves, front first; a piece over
// which the interval extension of F - T (its tape's interval evaluator)
// excludes 0 holds no surface and is dropped; a piece no longer than
// `accuracy` (POV-Ray's own tolerance, in object units) whose ends, or
// either end and its middle, differ in sign holds a crossing, refined by
// bisection to adjacent doubles; a piece without a sign change splits on
// to 1e-7 of the container (a ray grazing the surface crosses it over a
// short stretch). No crossing is missed but two within `accuracy` of each
// other inside one piece (a sliver thinner than the accuracy the scene
// asked for, which POV-Ray misses too). A ray whose pieces keep holding 0
// (F flat at T along it) stops splitting after 2^16 pieces and then looks
// at the ends of the pieces it holds only.
//
// An F that calls a function with no interval bound (a pigment function,
// runtime/time/point_function.hpp) is `sampled`: a piece is dropped, as
// POV-Ray's Function_Find_Root_R drops it, when F's values at its ends are
// too far from T for F to reach T between them with a slope of at most
// max_gradient (|f(a) + f(b)| > max_gradient * length, f = F - T), and
// pieces stop at `accuracy` with or without a sign change. The result is
// POV-Ray's: right where max_gradient holds, and a steeper F can miss the
// surface as it does in POV-Ray.
//
// Hits: part 0 on F = T, with POV-Ray's normal, F's forward differences
// over `accuracy` (not the exact gradient: the look and trace()'s normals
// are POV-Ray's), and its (1, 0, 0) where they are all zero; part 1 on the container's walls, with
// the wall's normal. uv (0, 0). inside: in C and F - T <= 0.
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "runtime/geometry/ray3.hpp"
#include "runtime/time/user_function.hpp"

namespace hexant::runtime::geometry {

struct IsosurfaceGeometry {
    SpaceFunction function;
    double time = 0.0;
    double threshold = 0.0;
    bool sphere = false;           // the container: a sphere, else a box
    glm::dvec3 lo{-1.0}, hi{1.0};  // the box
    glm::dvec3 center{0.0};        // the sphere
    double radius = 1.0;
    bool open = false;
    double accuracy = 0.001;
    // No interval bound of F: POV-Ray's search by max_gradient (above).
    bool sampled = false;
    double max_gradient = 1.1;
};

std::optional<SurfaceHit> intersect(const IsosurfaceGeometry& g, const Ray3& ray, double s_min,
                                    double s_max);
bool inside(const IsosurfaceGeometry& g, glm::dvec3 p);
Box3 object_bounds(const IsosurfaceGeometry& g);
bool surface_may_meet(const IsosurfaceGeometry& g, const Box3& box);

}  // namespace hexant::runtime::geometry
