#include "runtime/objects/julia_fractal/complex_functions.hpp"

#include <cmath>

namespace hexant::runtime::geometry {

namespace {

// Complex_Mult.
Complex mult(const Complex& a, const Complex& b) {
    const double x = a.x * b.x - a.y * b.y;
    return {x, a.x * b.y + a.y * b.x};
}

// Complex_Div; `unset` is what POV-Ray's target held before (it returns
// without writing when the divisor is 0).
Complex div(const Complex& a, const Complex& b, const Complex& unset) {
    const double mod = b.x * b.x + b.y * b.y;
    if (mod == 0) return unset;
    const double yxmod = b.x / mod;
    const double yymod = -b.y / mod;
    const double x = a.x * yxmod - a.y * yymod;
    return {x, a.x * yymod + a.y * yxmod};
}

// Complex_Ln.
Complex ln(const Complex& s) {
    const double mod = std::sqrt(s.x * s.x + s.y * s.y);
    return {std::log(mod), std::atan2(s.y, s.x)};
}

// Complex_Sqrt.
Complex sqrt_of(const Complex& s) {
    if (s.x == 0.0 && s.y == 0.0) return {0.0, 0.0};
    const double mag = std::sqrt(std::sqrt(s.x * s.x + s.y * s.y));
    const double theta = std::atan2(s.y, s.x) / 2;
    return {mag * std::cos(theta), mag * std::sin(theta)};
}

// Complex_ATanh; `unset` as for div (at +-1 POV-Ray writes nothing).
Complex atanh_of(const Complex& s, const Complex& unset) {
    if (s.x == 0.0) return {0, std::atan(s.y)};
    if (std::fabs(s.x) == 1.0 && s.y == 0.0) return unset;
    if (std::fabs(s.x) < 1.0 && s.y == 0.0) return {std::log((1 + s.x) / (1 - s.x)) / 2, 0};
    const Complex t0{1 + s.x, s.y};
    const Complex t1{1 - s.x, -s.y};
    const Complex t2 = ln(div(t0, t1, Complex{}));
    return {.5 * t2.x, .5 * t2.y};
}

// Complex_ATan (its call of Complex_ATanh writes in place: an unset result
// is its argument).
Complex atan_of(const Complex& s) {
    if (s.x == 0.0 && s.y == 0.0) return {0, 0};
    if (s.x != 0.0 && s.y == 0.0) return {std::atan(s.x), 0};
    if (s.x == 0.0 && s.y != 0.0) {
        const Complex t0{s.y, 0.0};
        const Complex r = atanh_of(t0, t0);
        return {-r.y, r.x};
    }
    if (s.x != 0.0 && s.y != 0.0) {
        const Complex t0{-s.y, s.x};
        const Complex t1{1 - t0.x, -t0.y};
        const Complex t2{1 + t0.x, t0.y};
        const Complex t3 = ln(div(t1, t2, Complex{}));
        return {-t3.y * .5, .5 * t3.x};
    }
    return {0, 0};  // NaN parts: POV-Ray writes nothing
}

}  // namespace

Complex complex_function(JuliaFunction f, const Complex& s, const Complex& exponent) {
    switch (f) {
        case JuliaFunction::exp: {
            const double expx = std::exp(s.x);
            return {expx * std::cos(s.y), expx * std::sin(s.y)};
        }
        case JuliaFunction::ln:
            return ln(s);
        case JuliaFunction::sin:
            return {std::sin(s.x) * std::cosh(s.y), std::cos(s.x) * std::sinh(s.y)};
        case JuliaFunction::asin: {
            // -i ln(i z + sqrt(1 - z^2))
            Complex t1 = mult(s, s);
            t1 = sqrt_of({1 - t1.x, -t1.y});
            t1 = ln({t1.x + -s.y, t1.y + s.x});
            return {t1.y, -t1.x};
        }
        case JuliaFunction::cos:
            return {std::cos(s.x) * std::cosh(s.y), -std::sin(s.x) * std::sinh(s.y)};
        case JuliaFunction::acos: {
            Complex t = mult(s, s);
            t = sqrt_of({t.x - 1, t.y});
            t = ln({t.x + s.x, t.y + s.y});
            return {t.y, -t.x};
        }
        case JuliaFunction::tan: {
            const double x = 2 * s.x, y = 2 * s.y;
            const double denom = std::cos(x) + std::cosh(y);
            if (denom == 0) return {0, 0};
            return {std::sin(x) / denom, std::sinh(y) / denom};
        }
        case JuliaFunction::atan:
            return atan_of(s);
        case JuliaFunction::sinh:
            return {std::sinh(s.x) * std::cos(s.y), std::cosh(s.x) * std::sin(s.y)};
        case JuliaFunction::asinh: {
            Complex t = mult(s, s);
            t = sqrt_of({t.x + 1, t.y});
            return ln({t.x + s.x, t.y + s.y});
        }
        case JuliaFunction::cosh:
            return {std::cosh(s.x) * std::cos(s.y), std::sinh(s.x) * std::sin(s.y)};
        case JuliaFunction::acosh: {
            Complex t = mult(s, s);
            t = sqrt_of({t.x - 1, t.y});
            return ln({s.x + t.x, s.y + t.y});
        }
        case JuliaFunction::tanh: {
            const double x = 2 * s.x, y = 2 * s.y;
            const double denom = std::cosh(x) + std::cos(y);
            if (denom == 0) return {0, 0};
            return {std::sinh(x) / denom, std::sin(y) / denom};
        }
        case JuliaFunction::atanh:
            return atanh_of(s, Complex{});
        case JuliaFunction::pwr: {
            if (s.x == 0 && s.y == 0) return {0.0, 0.0};
            const Complex t = mult(ln(s), exponent);
            const double e2x = t.x < -690 ? 0 : std::exp(t.x);
            return {e2x * std::cos(t.y), e2x * std::sin(t.y)};
        }
        default:
            return s;  // the algebraic maps are not complex functions
    }
}

void hypercomplex_function(JuliaFunction f, const Complex& exponent, double x, double y, double z,
                           double w, double& xr, double& yr, double& zr, double& wr) {
    // The duplex form, each half through f, and back.
    const Complex a{x - w, y + z}, b{x + w, y - z};
    const Complex ra = complex_function(f, a, exponent);
    const Complex rb = complex_function(f, b, exponent);
    xr = .5 * (ra.x + rb.x);
    yr = .5 * (ra.y + rb.y);
    zr = .5 * (ra.y - rb.y);
    wr = .5 * (rb.x - ra.x);
}

}  // namespace hexant::runtime::geometry
