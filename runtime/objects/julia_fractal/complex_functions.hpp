// The complex functions of POV-Ray 3.7's hypercomplex julia_fractal
// (hcmplx.cpp: Complex_Exp ... Complex_Pwr), written as POV-Ray writes
// them so that the iterations agree with its own to the last bit where
// the libm agrees. A hypercomplex number is taken apart into two complex
// numbers (its "duplex" form, HFunc), each goes through the function, and
// the results are put back together.
#pragma once

namespace hexant::runtime::geometry {

struct Complex {
    double x = 0.0, y = 0.0;
};

// The functions a hypercomplex julia_fractal may iterate, in POV-Ray's
// order (fractal.h's STYPE list: the complex functions first, then the
// algebraic maps).
enum class JuliaFunction {
    exp,
    ln,
    sin,
    asin,
    cos,
    acos,
    tan,
    atan,
    sinh,
    asinh,
    cosh,
    acosh,
    tanh,
    atanh,
    pwr,
    sqr,
    cube,
    reciprocal
};

// f(source) for one of the complex functions (exp .. pwr); `exponent` is
// pwr's. Where POV-Ray leaves its result unset (a division by zero in
// Complex_Div, Complex_Tan or Complex_Tanh, atanh at +-1), the result is 0,
// not whatever was in memory.
Complex complex_function(JuliaFunction f, const Complex& source, const Complex& exponent);

// POV-Ray's HFunc: f applied to the hypercomplex number (x, y, z, w).
void hypercomplex_function(JuliaFunction f, const Complex& exponent, double x, double y, double z,
                           double w, double& xr, double& yr, double& zr, double& wr);

}  // namespace hexant::runtime::geometry
