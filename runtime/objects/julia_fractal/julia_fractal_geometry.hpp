// POV-Ray 3.7's julia_fractal in object space at one instant (fractal.cpp,
// quatern.cpp, hcmplx.cpp): the 3D slice of a 4D Julia set of q -> f(q) + c
// over the quaternions or the hypercomplex numbers
// (runtime/objects/julia_fractal/julia_iteration.hpp).
//
// Hits are found as POV-Ray finds them (Fractal::All_Intersections): the
// ray is clipped to the bounding sphere (F_Bound), then marched in steps of
// the distance estimate, never shorter than 1/precision, until the inside
// test changes; the crossing is then halved down to 1e-7. So a part of the
// set thinner than a step can be stepped over, as in POV-Ray. The hit's
// normal is POV-Ray's (Normal_Calc over max_iteration steps).
//
// No NaN or Inf leaves these routines: a NaN step is taken as the
// smallest step, a march is cut at 2^22 steps (a precision of 10^6 on the
// largest sphere), and a normal that is zero or not finite becomes the
// reverse of the ray.
#pragma once

#include <optional>

#include "runtime/geometry/ray3.hpp"
#include "runtime/objects/julia_fractal/julia_iteration.hpp"

namespace hexant::runtime::geometry {

// The geometry of the given parameters, with POV-Ray's derived values
// (Parse_Julia_Fractal, Compute_BBox): the slice normalised (invalid if
// |slice|^2 or its fourth component is below 1e-10), iterations at least
// 1, the step 1 / max(precision, 1), and the exit value and sphere.
JuliaFractalGeometry make_julia_fractal(const std::array<double, 4>& c, JuliaAlgebra algebra,
                                        JuliaFunction function, Complex exponent, int iterations,
                                        double precision, const std::array<double, 4>& slice,
                                        double slice_distance);

// A radius beyond which no point is inside, at least sqrt(exit_value).
double julia_reach(const JuliaFractalGeometry& g);

std::optional<SurfaceHit> intersect(const JuliaFractalGeometry& g, const Ray3& ray, double s_min,
                                    double s_max);
bool inside(const JuliaFractalGeometry& g, glm::dvec3 p);
Box3 object_bounds(const JuliaFractalGeometry& g);
bool surface_may_meet(const JuliaFractalGeometry& g, const Box3& box);

}  // namespace hexant::runtime::geometry
