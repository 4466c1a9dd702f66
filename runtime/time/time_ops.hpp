// How each TimeOp acts on numbers, written once for any number type so that
// the point evaluator (and later the interval and derivative evaluators) and
// the constant folder share one definition of POV-Ray's semantics.
#pragma once

#include <cmath>

#include "image/colour_transfer.hpp"
#include "runtime/time/time_function.hpp"

namespace hexant::runtime {

// POV-Ray's tolerance for =, != and the truth of a float (parser EPSILON).
inline constexpr double kPovEpsilon = 1e-10;

inline bool pov_true(double v) {
    return std::fabs(v) > kPovEpsilon;
}

// Apply a non-spline operation to plain doubles.
inline double apply_op(TimeOp op, double a, double b = 0.0, double c = 0.0) {
    constexpr double pi = 3.14159265358979323846;
    (void)pi;
    switch (op) {
        case TimeOp::Constant:
        case TimeOp::Clock:
        case TimeOp::Argument:
        case TimeOp::SplineComponent:
        case TimeOp::PointCall:
            return a;
        case TimeOp::Negate:
            return -a;
        case TimeOp::Not:
            return pov_true(a) ? 0.0 : 1.0;
        case TimeOp::Abs:
            return std::fabs(a);
        case TimeOp::Sin:
            return std::sin(a);
        case TimeOp::Cos:
            return std::cos(a);
        case TimeOp::Tan:
            return std::tan(a);
        case TimeOp::Asin:
            return std::asin(a);
        case TimeOp::Acos:
            return std::acos(a);
        case TimeOp::Atan:
            return std::atan(a);
        case TimeOp::Sqrt:
            return std::sqrt(a);
        case TimeOp::Exp:
            return std::exp(a);
        case TimeOp::Log10:
            return std::log10(a);
        case TimeOp::Ln:
            return std::log(a);
        case TimeOp::Int:
            return std::trunc(a);
        case TimeOp::Floor:
            return std::floor(a);
        case TimeOp::Ceil:
            return std::ceil(a);
        case TimeOp::SrgbDecode:
            return image::srgb_decode(a);
        case TimeOp::Add:
            return a + b;
        case TimeOp::Subtract:
            return a - b;
        case TimeOp::Multiply:
            return a * b;
        case TimeOp::Divide:
            return a / b;
        case TimeOp::Pow:
            return std::pow(a, b);
        case TimeOp::Atan2:
            return std::atan2(a, b);
        case TimeOp::Min:
            return a < b ? a : b;
        case TimeOp::Max:
            return a > b ? a : b;
        case TimeOp::Mod:
            return std::fmod(a, b);
        case TimeOp::IntDiv:
            return std::trunc(a / b);
        case TimeOp::Less:
            return a < b ? 1.0 : 0.0;
        case TimeOp::LessEqual:
            return a <= b ? 1.0 : 0.0;
        case TimeOp::Equal:
            return std::fabs(a - b) < kPovEpsilon ? 1.0 : 0.0;
        case TimeOp::NotEqual:
            return std::fabs(a - b) < kPovEpsilon ? 0.0 : 1.0;
        case TimeOp::GreaterEqual:
            return a >= b ? 1.0 : 0.0;
        case TimeOp::Greater:
            return a > b ? 1.0 : 0.0;
        case TimeOp::And:
            return (pov_true(a) && pov_true(b)) ? 1.0 : 0.0;
        case TimeOp::Or:
            return (pov_true(a) || pov_true(b)) ? 1.0 : 0.0;
        case TimeOp::Select:
            return a < 0.0 ? b : c;
        case TimeOp::Conditional:
            return pov_true(a) ? b : c;
    }
    return a;
}

}  // namespace hexant::runtime
