// Storing bounds in single precision without losing anything (cell.hpp).
//
// A static bound is a float rounded outward: the traversal loads it as it
// is. A bound evaluated at traversal time (a linear-motion box at the ray's
// instant, a 12-slab's diagonal at it) also picks up the rounding of that
// evaluation in float, so its stored ends are pushed outward by a margin
// first:
//  - Linear: the ray computes lo = fma(u, D, L0) with u = (t - t0) /
//    (t1 - t0) rounded to float (|u - u_exact| <= 2^-24, since u lies in
//    [0, 1]) and one rounding of the fma (<= 2^-24 of its result), so it is
//    off by at most 2^-24 (|L0| + 2 |D|) <= 3 * 2^-24 (|a0| + |a1|) from the
//    exact L0 + u D, where a0 and a1 are the line's ends. Lowering both ends
//    by 2^-21 (|a0| + |a1|) (eight times 2^-24 of the same) covers it; then
//    L0 is a0 rounded down and D is (a1 - L0) rounded down (checked in
//    double), so L0 + u D lies below the lowered line for all u in [0, 1].
//  - Diagonal slab at an instant: the ray computes lo - h with h = t / 2
//    rounded to float, off by at most 2^-24 (|lo| + |t|); the margin
//    2^-21 (|lo| + |t|max) covers it likewise.
// Non-finite ends stay infinite (and a line with one becomes a constant
// infinite end, so that no inf - inf ever forms a NaN).
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace hexant::tracer {

inline constexpr double kEvaluationMargin = 0x1p-21;
// A PieceNode's knots move out by this much of the largest knot's
// magnitude along their axis (tracer/node_piece.cpp argues it).
inline constexpr double kPieceMargin = 0x1p-19;

// The next float above f (f not NaN, not +inf), and below (not -inf): a
// step of the bit pattern, inline where std::nextafter is a library call
// on the walk's path (the nearest hit's float bound is taken per hit).
inline float float_step_up(float f) {
    if (f == 0.0f) return std::numeric_limits<float>::denorm_min();
    const std::uint32_t b = std::bit_cast<std::uint32_t>(f);
    return std::bit_cast<float>(f > 0.0f ? b + 1 : b - 1);
}
inline float float_step_down(float f) {
    return -float_step_up(-f);
}

// The largest float <= v, and the smallest >= v (NaN gives -inf / +inf).
inline float float_down(double v) {
    if (!(v == v)) return -std::numeric_limits<float>::infinity();
    float f = static_cast<float>(v);
    if (static_cast<double>(f) > v) f = float_step_down(f);
    return f;
}
inline float float_up(double v) {
    if (!(v == v)) return std::numeric_limits<float>::infinity();
    float f = static_cast<float>(v);
    if (static_cast<double>(f) < v) f = float_step_up(f);
    return f;
}

// A lower end moving linearly from a0 (u = 0) to a1 (u = 1) as float
// (L0, D), such that the float evaluation fma(u, D, L0) at any u in [0, 1]
// stays at or below a0 + u (a1 - a0). `upper` gives the mirror image: an
// upper end whose evaluation stays at or above the line.
struct LinearEnd {
    float start, change;
};

inline LinearEnd linear_end(double a0, double a1, bool upper) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    const float sign = upper ? 1.0f : -1.0f;
    if (!std::isfinite(a0) || !std::isfinite(a1) || (a0 == 0.0 && a1 == 0.0)) {
        // An infinite end, or a constant zero: no evaluation error at all.
        if (a0 == 0.0 && a1 == 0.0) return {0.0f, 0.0f};
        return {static_cast<float>(sign * inf), 0.0f};
    }
    const double e = kEvaluationMargin * (std::fabs(a0) + std::fabs(a1));
    const double s = upper ? 1.0 : -1.0;
    const double b0 = a0 + s * e, b1 = a1 + s * e;
    const float start = upper ? float_up(b0) : float_down(b0);
    if (!std::isfinite(start)) return {static_cast<float>(sign * inf), 0.0f};
    float change = upper ? float_up(b1 - double(start)) : float_down(b1 - double(start));
    // (start + change) in double is exact or within an ulp of double, far
    // inside the margin; the loop only guards against the rounding of the
    // subtraction above.
    for (int guard = 0; guard < 4; ++guard) {
        const double end = double(start) + double(change);
        if (upper ? end >= b1 : end <= b1) break;
        change = std::nextafter(change, sign * std::numeric_limits<float>::infinity());
    }
    if (!std::isfinite(change)) return {static_cast<float>(sign * inf), 0.0f};
    return {start, change};
}

// A diagonal slab end stored for evaluation at instants with |t| <= t_max.
inline float slab_end(double v, double t_max, bool upper) {
    if (!std::isfinite(v)) return upper ? float_up(v) : float_down(v);
    const double e = kEvaluationMargin * (std::fabs(v) + t_max);
    return upper ? float_up(v + e) : float_down(v - e);
}

}  // namespace hexant::tracer
