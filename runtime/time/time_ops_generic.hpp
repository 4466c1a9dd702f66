// How each TimeOp acts on intervals and on dual numbers, beside
// time_ops.hpp's apply_op for doubles (POV-Ray's meaning). The overloads keep
// one name, so a template over the number type calls apply_op(op, a, b, c)
// for double, Interval and Dual alike.
//
// Interval: the result contains the double result for every choice of
// arguments inside the argument intervals. A truth value (comparisons, !, &,
// |) is [1, 1] or [0, 0] when every choice agrees and [0, 1] otherwise; a
// choice (select, ?:) whose condition is undecided takes the hull of both
// branches.
//
// Dual: the value is the double result, bit for bit (the same expressions);
// the derivative is that of the branch the value took, 0 for steps and truth
// values.
#pragma once

#include <cmath>

#include "runtime/time/dual.hpp"
#include "runtime/time/interval.hpp"
#include "runtime/time/time_function.hpp"
#include "runtime/time/time_ops.hpp"

namespace hexant::runtime {

namespace time_ops_detail {

inline constexpr double kSrgbKnee = 0.04045;

inline const Interval kUndecided{0.0, 1.0};

// POV-Ray's truth of every value in a: |v| > kPovEpsilon.
inline Interval truth(const Interval& a) {
    if (a.lo > kPovEpsilon || a.hi < -kPovEpsilon) return 1.0;
    if (a.lo >= -kPovEpsilon && a.hi <= kPovEpsilon) return 0.0;
    return kUndecided;
}

inline Interval decided(bool all_true, bool all_false) {
    return all_true ? Interval(1.0) : all_false ? Interval(0.0) : kUndecided;
}

inline Interval less(const Interval& a, const Interval& b) {
    return decided(a.hi < b.lo, a.lo >= b.hi);
}
inline Interval less_equal(const Interval& a, const Interval& b) {
    return decided(a.hi <= b.lo, a.lo > b.hi);
}
// |a - b| < kPovEpsilon; the interval difference holds the rounded difference.
inline Interval equal(const Interval& a, const Interval& b) {
    const Interval d = a - b;
    return decided(d.lo > -kPovEpsilon && d.hi < kPovEpsilon,
                   d.lo >= kPovEpsilon || d.hi <= -kPovEpsilon);
}
inline Interval negate_truth(const Interval& t) {
    return {1.0 - t.hi, 1.0 - t.lo};
}

// std::fmod(a, b): exact, with a's sign and less than |b| in size. When the
// quotient's integer part is the same everywhere it is a - q b exactly.
inline Interval fmod(const Interval& a, const Interval& b) {
    // Two points: std::fmod is exact (a quotient rounded outward would
    // straddle an integer when a / b is one: mod(2, 2) was [0, 2]).
    if (a.is_point() && b.is_point()) return Interval(std::fmod(a.lo, b.lo));
    const double m = b.magnitude();
    Interval r{a.lo >= 0.0 ? 0.0 : -std::min(-a.lo, m), a.hi <= 0.0 ? 0.0 : std::min(a.hi, m)};
    const Interval q = trunc(a / b);
    if (q.lo == q.hi && std::isfinite(q.lo)) {
        const Interval exact = intersect(r, a - q * b);
        if (!exact.is_empty()) r = exact;
    }
    return r;
}

// trunc(a / b), as the point evaluator computes it. Two points give its
// double (a quotient rounded outward straddled the integer when a / b is
// one: div(4, 2) was [1, 2], which left a condition on it undecided).
inline Interval int_div(const Interval& a, const Interval& b) {
    if (a.is_point() && b.is_point()) return Interval(std::trunc(a.lo / b.lo));
    return trunc(a / b);
}

inline Interval srgb_decode(const Interval& c) {
    const auto power = [](const Interval& x) { return pow((x + 0.055) / 1.055, Interval(2.4)); };
    if (c.hi <= kSrgbKnee) return c / 12.92;
    if (c.lo > kSrgbKnee) return power(c);
    // Both pieces; the power piece's limit at the knee is included.
    return hull(Interval(c.lo, kSrgbKnee) / 12.92, power(Interval(kSrgbKnee, c.hi)));
}

inline Dual srgb_decode(const Dual& c) {
    const double v = image::srgb_decode(c.v);
    if (c.v <= kSrgbKnee) return {v, c.d / 12.92};
    return {v, 2.4 * std::pow((c.v + 0.055) / 1.055, 1.4) / 1.055 * c.d};
}

}  // namespace time_ops_detail

// Apply a non-spline operation to intervals.
inline Interval apply_op(TimeOp op, const Interval& a, const Interval& b = 0.0,
                         const Interval& c = 0.0) {
    namespace d = time_ops_detail;
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
            return d::negate_truth(d::truth(a));
        case TimeOp::Abs:
            return abs(a);
        case TimeOp::Sin:
            return sin(a);
        case TimeOp::Cos:
            return cos(a);
        case TimeOp::Tan:
            return tan(a);
        case TimeOp::Asin:
            return asin(a);
        case TimeOp::Acos:
            return acos(a);
        case TimeOp::Atan:
            return atan(a);
        case TimeOp::Sqrt:
            return sqrt(a);
        case TimeOp::Exp:
            return exp(a);
        case TimeOp::Log10:
            return log10(a);
        case TimeOp::Ln:
            return log(a);
        case TimeOp::Int:
            return trunc(a);
        case TimeOp::Floor:
            return floor(a);
        case TimeOp::Ceil:
            return ceil(a);
        case TimeOp::SrgbDecode:
            return d::srgb_decode(a);
        case TimeOp::Add:
            return a + b;
        case TimeOp::Subtract:
            return a - b;
        case TimeOp::Multiply:
            return a * b;
        case TimeOp::Divide:
            return a / b;
        case TimeOp::Pow:
            return pow(a, b);
        case TimeOp::Atan2:
            return atan2(a, b);
        case TimeOp::Min:
            return min(a, b);
        case TimeOp::Max:
            return max(a, b);
        case TimeOp::Mod:
            return d::fmod(a, b);
        case TimeOp::IntDiv:
            return d::int_div(a, b);
        case TimeOp::Less:
            return d::less(a, b);
        case TimeOp::LessEqual:
            return d::less_equal(a, b);
        case TimeOp::Equal:
            return d::equal(a, b);
        case TimeOp::NotEqual:
            return d::negate_truth(d::equal(a, b));
        case TimeOp::GreaterEqual:
            return d::less_equal(b, a);
        case TimeOp::Greater:
            return d::less(b, a);
        case TimeOp::And: {
            const Interval ta = d::truth(a), tb = d::truth(b);
            return d::decided(ta.lo == 1.0 && tb.lo == 1.0, ta.hi == 0.0 || tb.hi == 0.0);
        }
        case TimeOp::Or: {
            const Interval ta = d::truth(a), tb = d::truth(b);
            return d::decided(ta.lo == 1.0 || tb.lo == 1.0, ta.hi == 0.0 && tb.hi == 0.0);
        }
        case TimeOp::Select:
            if (a.hi < 0.0) return b;
            if (a.lo >= 0.0) return c;
            return hull(b, c);
        case TimeOp::Conditional: {
            const Interval t = d::truth(a);
            if (t.lo == 1.0) return b;
            if (t.hi == 0.0) return c;
            return hull(b, c);
        }
    }
    return a;
}

// Apply a non-spline operation to dual numbers.
inline Dual apply_op(TimeOp op, const Dual& a, const Dual& b = 0.0, const Dual& c = 0.0) {
    // Values without derivative: truth values and steps.
    const auto flat = [&] { return Dual(apply_op(op, a.v, b.v, c.v), 0.0); };
    switch (op) {
        case TimeOp::Constant:
        case TimeOp::Clock:
        case TimeOp::Argument:
        case TimeOp::SplineComponent:
        case TimeOp::PointCall:
            return a;
        case TimeOp::Negate:
            return -a;
        case TimeOp::Abs:
            return abs(a);
        case TimeOp::Sin:
            return sin(a);
        case TimeOp::Cos:
            return cos(a);
        case TimeOp::Tan:
            return tan(a);
        case TimeOp::Asin:
            return asin(a);
        case TimeOp::Acos:
            return acos(a);
        case TimeOp::Atan:
            return atan(a);
        case TimeOp::Sqrt:
            return sqrt(a);
        case TimeOp::Exp:
            return exp(a);
        case TimeOp::Log10:
            return log10(a);
        case TimeOp::Ln:
            return log(a);
        case TimeOp::SrgbDecode:
            return time_ops_detail::srgb_decode(a);
        case TimeOp::Add:
            return a + b;
        case TimeOp::Subtract:
            return a - b;
        case TimeOp::Multiply:
            return a * b;
        case TimeOp::Divide:
            return a / b;
        case TimeOp::Pow:
            return pow(a, b);
        case TimeOp::Atan2:
            return atan2(a, b);
        case TimeOp::Min:
            return min(a, b);
        case TimeOp::Max:
            return max(a, b);
        // fmod(a, b) = a - q b with q = trunc(a / b) constant nearby.
        case TimeOp::Mod:
            return {std::fmod(a.v, b.v), a.d - std::trunc(a.v / b.v) * b.d};
        case TimeOp::Not:
        case TimeOp::Int:
        case TimeOp::Floor:
        case TimeOp::Ceil:
        case TimeOp::IntDiv:
        case TimeOp::Less:
        case TimeOp::LessEqual:
        case TimeOp::Equal:
        case TimeOp::NotEqual:
        case TimeOp::GreaterEqual:
        case TimeOp::Greater:
        case TimeOp::And:
        case TimeOp::Or:
            return flat();
        case TimeOp::Select:
            return a.v < 0.0 ? b : c;
        case TimeOp::Conditional:
            return pov_true(a.v) ? b : c;
    }
    return a;
}

}  // namespace hexant::runtime
