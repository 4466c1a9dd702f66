// The doubles a time function's point evaluation can give over an interval
// of times: the number type runtime/time/switching_instants.hpp splits time
// with. It is an Interval whose sums, differences, products and quotients
// round their ends to nearest instead of outward: rounding to nearest is
// monotone, so for doubles x in a and y in b, fl(x + y) lies between
// fl(a.lo + b.lo) and fl(a.hi + b.hi) (and a product or quotient between
// the nearest-rounded corners). It holds every point value, which is all
// a switch of the point evaluation needs, and not always the exact real
// result: near clock 0, 10 - clock * 10 is exactly 10 in doubles for some
// 2^60 instants, below 10 in reals, and an outward-rounded interval never
// decided int() of it there. Every other operation is the Interval's
// (outward, so it holds point values too: libm functions carry their ulps).
#pragma once

#include <cmath>
#include <limits>

#include "runtime/time/interval.hpp"
#include "runtime/time/time_ops_generic.hpp"

namespace hexant::runtime {

struct PointRange {
    Interval v;
    PointRange(double x = 0.0) : v(x) {}  // NOLINT: numbers are ranges
    explicit PointRange(const Interval& i) : v(i) {}
};

namespace point_range_detail {

inline double low(double x) {
    return x != x ? -std::numeric_limits<double>::infinity() : x;
}
inline double high(double x) {
    return x != x ? std::numeric_limits<double>::infinity() : x;
}

inline Interval sum(const Interval& a, const Interval& b) {
    return {low(a.lo + b.lo), high(a.hi + b.hi)};
}

inline Interval product(const Interval& a, const Interval& b) {
    using interval_detail::max4;
    using interval_detail::min4;
    const double p1 = a.lo * b.lo, p2 = a.lo * b.hi, p3 = a.hi * b.lo, p4 = a.hi * b.hi;
    return {low(min4(p1, p2, p3, p4)), high(max4(p1, p2, p3, p4))};
}

inline Interval quotient(const Interval& a, const Interval& b) {
    using interval_detail::max4;
    using interval_detail::min4;
    if (b.contains_zero()) return Interval::entire();
    const double q1 = a.lo / b.lo, q2 = a.lo / b.hi, q3 = a.hi / b.lo, q4 = a.hi / b.hi;
    return {low(min4(q1, q2, q3, q4)), high(max4(q1, q2, q3, q4))};
}

}  // namespace point_range_detail

inline PointRange apply_op(TimeOp op, const PointRange& a, const PointRange& b = 0.0,
                           const PointRange& c = 0.0) {
    namespace d = point_range_detail;
    switch (op) {
        case TimeOp::Add:
            return PointRange(d::sum(a.v, b.v));
        case TimeOp::Subtract:
            return PointRange(d::sum(a.v, -b.v));
        case TimeOp::Multiply:
            return PointRange(d::product(a.v, b.v));
        case TimeOp::Divide:
            return PointRange(d::quotient(a.v, b.v));
        default:
            return PointRange(apply_op(op, a.v, b.v, c.v));
    }
}

}  // namespace hexant::runtime
