// Interval jets: a time function's range and its first two derivatives'
// ranges over a piece of time, with the double evaluation's rounding
// radius, for sweeps that follow the motion by chords (time_sweep.hpp).
//
// Over a time interval T an IntervalJet holds:
//   v  - an interval holding f(t), exact and as the double evaluator rounds
//        it, for every t in T (the Interval evaluator's answer: the same
//        operations in the same order);
//   d  - an interval holding f'(t) on T;
//   dd - an interval holding f''(t) on T. f is twice differentiable with
//        f' absolutely continuous on T: no jump and no kink inside (a step
//        that changes, a comparison that flips, abs, min or max at their
//        corner, a spline's joints make d and dd entire()). Then a chord
//        misses f by at most (t - t0)(t1 - t) / 2 * max|f''| <= (t1 - t0)^2
//        / 8 * max|f''| (the interpolation error of a line; Davis,
//        "Interpolation and Approximation", theorem 3.1.1);
//   r  - the rounding radius: |double evaluation - exact f| <= r on T, by
//        forward error analysis (a correctly rounded operation adds half an
//        ulp of its result, here a whole one to spare; libm's sin, cos and
//        exp kLibmUlps ulps, interval.hpp's assumption). Infinity where no
//        bound is worked out.
// Operations cover what motions use (arithmetic, sin, cos, sqrt, exp, a
// constant power, the steps where they do not change); the others answer
// with their interval value and entire derivatives: "no chord bound here".
#pragma once

#include <cmath>
#include <limits>

#include "runtime/time/interval.hpp"
#include "runtime/time/time_function.hpp"
#include "runtime/time/time_ops.hpp"
#include "runtime/time/time_ops_generic.hpp"

namespace hexant::runtime {

struct IntervalJet {
    Interval v{0.0};
    Interval d{0.0};
    Interval dd{0.0};
    double r = 0.0;

    IntervalJet(double value = 0.0)  // NOLINT: implicit, numbers are constants
        : v(value), r(value == value ? 0.0 : interval_detail::kInf) {}
    IntervalJet(const Interval& value, const Interval& first, const Interval& second, double radius)
        : v(value), d(first), dd(second), r(radius) {}

    // The time variable over t: derivative 1, exact.
    static IntervalJet variable(const Interval& t) {
        return {t, Interval(1.0), Interval(0.0), 0.0};
    }
    // A value with no derivatives to speak of (a jump or a kink inside).
    static IntervalJet unknown(const Interval& value) {
        return {value, Interval::entire(), Interval::entire(), interval_detail::kInf};
    }
    // Are the derivatives and the rounding radius bounded?
    bool smooth() const {
        return std::isfinite(dd.lo) && std::isfinite(dd.hi) && std::isfinite(d.lo) &&
               std::isfinite(d.hi) && std::isfinite(r);
    }
    bool is_exact_constant() const {
        return r == 0.0 && d.lo == 0.0 && d.hi == 0.0 && dd.lo == 0.0 && dd.hi == 0.0 &&
               v.is_point() && std::isfinite(v.lo);
    }
};

namespace interval_jet_detail {

inline constexpr double kUlp = std::numeric_limits<double>::epsilon();  // 2^-52

// Rounding radius after one correctly rounded operation whose exact result
// lies in v and whose arguments carried radius r into it.
inline double rounded(const Interval& v, double r) {
    return r + kUlp * (v.magnitude() + r);
}
// The same for a libm function (kLibmUlps ulps).
inline double libm_rounded(const Interval& v, double r) {
    return r + interval_detail::kLibmUlps * kUlp * (v.magnitude() + r);
}
// Every double and exact value of the argument.
inline Interval widened(const IntervalJet& a) {
    return {a.v.lo - a.r, a.v.hi + a.r};
}
// A step's value where it cannot change over the piece for double and exact
// arguments alike: derivatives 0, no rounding; else unknown.
inline IntervalJet step(const Interval& decided, const Interval& value) {
    if (decided.is_point() && std::isfinite(decided.lo))
        return {Interval(decided.lo), Interval(0.0), Interval(0.0), 0.0};
    return IntervalJet::unknown(value);
}

}  // namespace interval_jet_detail

// k x for an exact constant k.
inline IntervalJet scaled(const IntervalJet& x, double k) {
    if (k == 0.0) return IntervalJet(0.0);
    if (k == 1.0) return x;
    if (k == -1.0) return {-x.v, -x.d, -x.dd, x.r};
    const Interval v = interval_detail::scaled(x.v, k);
    return {v, interval_detail::scaled(x.d, k), interval_detail::scaled(x.dd, k),
            interval_jet_detail::rounded(v, std::fabs(k) * x.r)};
}

inline IntervalJet operator-(const IntervalJet& a) {
    return {-a.v, -a.d, -a.dd, a.r};
}
inline IntervalJet operator+(const IntervalJet& a, const IntervalJet& b) {
    const Interval v = a.v + b.v;
    return {v, a.d + b.d, a.dd + b.dd, interval_jet_detail::rounded(v, a.r + b.r)};
}
inline IntervalJet operator-(const IntervalJet& a, const IntervalJet& b) {
    const Interval v = a.v - b.v;
    return {v, a.d - b.d, a.dd - b.dd, interval_jet_detail::rounded(v, a.r + b.r)};
}
// (ab)'' = a'' b + 2 a' b' + a b''; (a + e)(b + f) - ab = af + eb + ef.
inline IntervalJet operator*(const IntervalJet& a, const IntervalJet& b) {
    if (b.is_exact_constant()) return scaled(a, b.v.lo);
    if (a.is_exact_constant()) return scaled(b, a.v.lo);
    const Interval v = a.v * b.v;
    const double carried = a.v.magnitude() * b.r + b.v.magnitude() * a.r + a.r * b.r;
    return {v, a.d * b.v + a.v * b.d, a.dd * b.v + Interval(2.0) * (a.d * b.d) + a.v * b.dd,
            interval_jet_detail::rounded(v, carried)};
}
// q = a/b: q' = (a' - q b')/b, q'' = (a'' - 2 q' b' - q b'')/b;
// (a + e)/(b + f) - a/b = (e - q f)/(b + f).
inline IntervalJet operator/(const IntervalJet& a, const IntervalJet& b) {
    const Interval q = a.v / b.v;
    const double below = b.v.mignitude() - b.r;
    if (!(below > 0.0)) return IntervalJet::unknown(q);
    const Interval q1 = (a.d - q * b.d) / b.v;
    const Interval q2 = (a.dd - Interval(2.0) * (q1 * b.d) - q * b.dd) / b.v;
    return {q, q1, q2, interval_jet_detail::rounded(q, (a.r + q.magnitude() * b.r) / below)};
}
inline IntervalJet& operator+=(IntervalJet& a, const IntervalJet& b) {
    return a = a + b;
}
inline IntervalJet& operator-=(IntervalJet& a, const IntervalJet& b) {
    return a = a - b;
}
inline IntervalJet& operator*=(IntervalJet& a, const IntervalJet& b) {
    return a = a * b;
}
inline IntervalJet& operator/=(IntervalJet& a, const IntervalJet& b) {
    return a = a / b;
}

// (sin a)'' = cos(a) a'' - sin(a) a'^2; sin and cos are 1-Lipschitz.
inline IntervalJet sin(const IntervalJet& a) {
    const Interval s = sin(a.v), c = cos(a.v);
    return {s, c * a.d, c * a.dd - s * sqr(a.d),
            interval_jet_detail::libm_rounded(Interval(1.0), a.r)};
}
inline IntervalJet cos(const IntervalJet& a) {
    const Interval s = sin(a.v), c = cos(a.v);
    return {c, -(s * a.d), -(s * a.dd) - c * sqr(a.d),
            interval_jet_detail::libm_rounded(Interval(1.0), a.r)};
}
// r = sqrt(a): r' = a'/(2r), r'' = (a'' - 2 r'^2)/(2r);
// |sqrt(x + e) - sqrt(x)| <= |e| / (2 sqrt(min(x, x + e))).
inline IntervalJet sqrt(const IntervalJet& a) {
    const Interval v = sqrt(a.v);
    const double below = a.v.lo - a.r;
    if (!(below > 0.0)) return IntervalJet::unknown(v);
    const Interval twice = Interval(2.0) * v;
    const Interval r1 = a.d / twice;
    return {v, r1, (a.dd - Interval(2.0) * sqr(r1)) / twice,
            interval_jet_detail::rounded(v, a.r / (2.0 * std::sqrt(below)))};
}
inline IntervalJet sqr(const IntervalJet& a) {
    return a * a;
}
// (e^a)'' = e^a (a'' + a'^2); |exp(x + e) - exp(x)| <= exp(x) expm1(|e|).
inline IntervalJet exp(const IntervalJet& a) {
    const Interval v = exp(a.v);
    return {v, v * a.d, v * (a.dd + sqr(a.d)),
            interval_jet_detail::libm_rounded(v, v.hi * std::expm1(a.r))};
}
// abs, min and max are exact; smooth only away from their corners.
inline IntervalJet abs(const IntervalJet& a) {
    const Interval w = interval_jet_detail::widened(a);
    if (w.lo > 0.0) return a;
    if (w.hi < 0.0) return -a;
    return IntervalJet::unknown(abs(a.v));
}
inline IntervalJet min(const IntervalJet& a, const IntervalJet& b) {
    const Interval wa = interval_jet_detail::widened(a), wb = interval_jet_detail::widened(b);
    if (wa.hi < wb.lo) return a;
    if (wb.hi < wa.lo) return b;
    return IntervalJet::unknown(min(a.v, b.v));
}
inline IntervalJet max(const IntervalJet& a, const IntervalJet& b) {
    const Interval wa = interval_jet_detail::widened(a), wb = interval_jet_detail::widened(b);
    if (wa.lo > wb.hi) return a;
    if (wb.lo > wa.hi) return b;
    return IntervalJet::unknown(max(a.v, b.v));
}
// x^y for an exact constant y and x > 0 throughout:
// (x^y)' = y x^(y-1) x', (x^y)'' = y (y-1) x^(y-2) x'^2 + y x^(y-1) x'';
// |(x + e)^y - x^y| <= |y| max|x^(y-1)| |e| over the widened x.
inline IntervalJet pow(const IntervalJet& x, const IntervalJet& y) {
    const Interval v = pow(x.v, y.v);
    const Interval w = interval_jet_detail::widened(x);
    if (!(y.is_exact_constant() && w.lo > 0.0)) return IntervalJet::unknown(v);
    const Interval k = y.v, k1 = k - Interval(1.0), k2 = k - Interval(2.0);
    const Interval p1 = pow(x.v, k1), p2 = pow(x.v, k2);
    const double carried = std::fabs(k.lo) * pow(w, k1).magnitude() * x.r;
    return {v, k * p1 * x.d, k * k1 * p2 * sqr(x.d) + k * p1 * x.dd,
            interval_jet_detail::libm_rounded(v, carried)};
}

// Apply a non-spline operation: the value as the Interval evaluator gives
// it, derivatives and radius as above; steps, truth values and choices are
// constant where their arguments (widened by their radii) decide them, and
// unknown where they may jump.
inline IntervalJet apply_op(TimeOp op, const IntervalJet& a, const IntervalJet& b = 0.0,
                            const IntervalJet& c = 0.0) {
    namespace ij = interval_jet_detail;
    const auto value = [&] { return apply_op(op, a.v, b.v, c.v); };
    const auto decided = [&] {
        return ij::step(apply_op(op, ij::widened(a), ij::widened(b), ij::widened(c)), value());
    };
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
        case TimeOp::Sqrt:
            return sqrt(a);
        case TimeOp::Exp:
            return exp(a);
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
        case TimeOp::Min:
            return min(a, b);
        case TimeOp::Max:
            return max(a, b);
        // fmod is exact: a - q b where q = trunc(a / b) does not change.
        case TimeOp::Mod: {
            const Interval q = trunc(ij::widened(a) / ij::widened(b));
            if (!(q.is_point() && std::isfinite(q.lo))) return IntervalJet::unknown(value());
            return {value(), a.d - q * b.d, a.dd - q * b.dd, a.r + std::fabs(q.lo) * b.r};
        }
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
            return decided();
        case TimeOp::Select: {
            const Interval w = ij::widened(a);
            if (w.hi < 0.0) return b;
            if (w.lo >= 0.0) return c;
            return IntervalJet::unknown(value());
        }
        case TimeOp::Conditional: {
            const Interval w = ij::widened(a);
            if (w.lo > kPovEpsilon || w.hi < -kPovEpsilon) return b;
            if (w.lo >= -kPovEpsilon && w.hi <= kPovEpsilon) return c;
            return IntervalJet::unknown(value());
        }
        case TimeOp::Tan:
        case TimeOp::Asin:
        case TimeOp::Acos:
        case TimeOp::Atan:
        case TimeOp::Log10:
        case TimeOp::Ln:
        case TimeOp::SrgbDecode:
        case TimeOp::Atan2:
            break;
    }
    return IntervalJet::unknown(value());
}

}  // namespace hexant::runtime
