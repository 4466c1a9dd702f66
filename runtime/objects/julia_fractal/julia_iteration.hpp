// The iterations of POV-Ray 3.7's julia_fractal at one point, as its
// quatern.cpp and hcmplx.cpp compute them: a point p of object space is
// the 4D number q0 = (x, y, z, w) with w from the slice (the hyperplane
// slice . q = distance), and is inside when q_{i+1} = f(q_i) + c stays
// within the exit radius for max_iteration steps. The distance estimates
// that set the march's steps and the normals (the derivative of q_N
// carried through the steps) follow POV-Ray's formulas, including its
// quirks: the hypercomplex function iteration starts from z = y
// (Iteration_HCompl_Func), the hypercomplex "cube" iterates the square,
// and the normals read the iteration stack beyond an early exit.
#pragma once

#include <array>
#include <vector>

#include <glm/vec3.hpp>

#include "runtime/objects/julia_fractal/complex_functions.hpp"

namespace hexant::runtime::geometry {

enum class JuliaAlgebra { quaternion, hypercomplex };

struct JuliaFractalGeometry {
    std::array<double, 4> c{1.0, 0.0, 0.0, 0.0};      // Julia_Parm
    std::array<double, 4> slice{0.0, 0.0, 0.0, 1.0};  // unit normal of the slice
    double slice_distance = 0.0;
    JuliaAlgebra algebra = JuliaAlgebra::quaternion;
    JuliaFunction function = JuliaFunction::sqr;
    Complex exponent;         // pwr's
    int iterations = 20;      // Num_Iterations, >= 1
    double precision = 0.05;  // Precision: the march's smallest step
    double exit_value = 4.0;  // Exit_Value: |q|^2 beyond it escapes
    double radius = 2.0;      // the bounding sphere's (Compute_BBox's R)
    double radius_squared = 4.0;
    bool valid = false;
};

// The iteration stack, one row per component (POV-Ray's IterStack): kept
// per thread, as POV-Ray's is, since the normal reads entries that a
// shorter iteration left from an earlier one.
struct JuliaStack {
    std::array<std::vector<double>, 4> q;
    void ensure(int iterations);
};
JuliaStack& thread_julia_stack();

// POV-Ray's Iteration: whether p is inside.
bool julia_iterate(const JuliaFractalGeometry& g, const glm::dvec3& p, JuliaStack& s);
// POV-Ray's D_Iteration: the same answer, and in `dist` the step the march
// may take from p along the unit `direction`.
bool julia_distance_iterate(const JuliaFractalGeometry& g, const glm::dvec3& p,
                            const glm::dvec3& direction, double& dist, JuliaStack& s);
// POV-Ray's Normal_Calc over the stack's first `n_max` iterations: the
// normal (not unit) at the point last iterated.
glm::dvec3 julia_normal(const JuliaFractalGeometry& g, int n_max, const JuliaStack& s);

// Whether every point of the box has the same answer of julia_iterate
// (all inside, or all escaped), by the iteration in interval arithmetic
// with the double code's operations in its order. False when it cannot
// tell, and for the complex functions, which it does not bound.
bool julia_uniform_over(const JuliaFractalGeometry& g, const glm::dvec3& lo, const glm::dvec3& hi);

}  // namespace hexant::runtime::geometry
