// Closed intervals of doubles with outward rounding: the number type of the
// bound evaluator. Every operation returns an interval that contains the
// exact result for every point of its arguments, and also the double that
// the point evaluator computes there (rounding to nearest is monotone, so the
// rounded value at any point lies between the rounded values at the ends).
//
// Rounding: the basic operations and sqrt are correctly rounded (IEEE 754),
// so their ends are stepped one ulp outward. (Where time is split on a
// condition, runtime/time/point_range.hpp rounds sums and products to nearest:
// it bounds the point evaluator's values only.) The libm functions (sin, cos,
// tan, asin, acos, atan, atan2, exp, log, log10, pow) are within 1 ulp on
// glibc x86_64 (2 for log10; glibc manual, "Known Maximum Errors in Math
// Functions"); a point value inside may be off by that much the other way, so
// their ends are stepped kLibmUlps = 4 ulps outward, which covers both errors
// plus a change of binade between the end and the inside point.
//
// Infinite ends are allowed; entire() is [-inf, +inf]. No operation returns a
// NaN end: an indeterminate end (inf - inf, a NaN argument) becomes the
// matching infinity. Outside a function's domain the argument is clamped to
// the domain first (sqrt, log, log10 of negatives; asin, acos beyond [-1, 1];
// pow of negative bases with non-integer exponents), since the point
// evaluator has no value there to contain.
//
// The free functions are found by argument-dependent lookup, so templates can
// write `using std::sin; sin(x)` for double, Interval and Dual alike.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <ostream>

namespace hexant::runtime {

namespace interval_detail {

inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr double kPi = 3.14159265358979323846;
inline constexpr int kLibmUlps = 4;

// The next double towards +inf; NaN goes to +inf (an unknown upper end).
inline double next_up(double x) {
    if (x != x) return kInf;
    if (x == kInf) return x;
    if (x == 0.0) return std::numeric_limits<double>::denorm_min();
    auto bits = std::bit_cast<std::uint64_t>(x);
    bits = x > 0.0 ? bits + 1 : bits - 1;
    return std::bit_cast<double>(bits);
}

// The next double towards -inf; NaN goes to -inf (an unknown lower end).
inline double next_down(double x) {
    return -next_up(-x);
}

// The rounding error of s = a + b, exactly (Knuth's TwoSum: round to
// nearest, no overflow; TAOCP vol. 2, 4.2.2). NaN after an overflow or
// with an infinite argument.
inline double sum_error(double a, double b, double s) {
    const double bb = s - a;
    return (a - (s - bb)) + (b - bb);
}

inline double up(double x, int ulps) {
    for (int i = 0; i < ulps; ++i) x = next_up(x);
    return x;
}
inline double down(double x, int ulps) {
    for (int i = 0; i < ulps; ++i) x = next_down(x);
    return x;
}

// Whether phase + k * period may lie in [lo, hi] for some integer k. Errs
// towards yes: the quotients carry rounding and the doubles for pi are not
// pi, both within a few ulps relative to the quotient (+1 for the phase).
inline bool may_contain_periodic(double lo, double hi, double phase, double period) {
    const double a = (lo - phase) / period;
    const double b = (hi - phase) / period;
    const double margin =
        8.0 * std::numeric_limits<double>::epsilon() * (std::max(std::fabs(a), std::fabs(b)) + 1.0);
    return std::floor(b + margin) >= std::ceil(a - margin);
}

}  // namespace interval_detail

struct Interval {
    double lo, hi;

    // A point; NaN becomes entire() so that no NaN ever enters a bound.
    Interval(double v = 0.0)  // NOLINT: implicit on purpose, numbers are intervals
        : lo(v == v ? v : -interval_detail::kInf), hi(v == v ? v : interval_detail::kInf) {}
    // Requires lo <= hi (or an empty interval on purpose, see intersect).
    Interval(double lo_, double hi_) : lo(lo_), hi(hi_) {}

    static Interval entire() { return {-interval_detail::kInf, interval_detail::kInf}; }

    double width() const { return hi - lo; }
    // The middle, always inside for finite ends; 0 for entire().
    double mid() const {
        if (lo == -hi) return 0.0;
        const double m = 0.5 * lo + 0.5 * hi;  // halves first: no overflow
        return std::clamp(m, lo, hi);
    }
    double magnitude() const { return std::max(std::fabs(lo), std::fabs(hi)); }
    // The smallest |x| over the interval (0 when it holds 0).
    double mignitude() const {
        return contains_zero() ? 0.0 : std::min(std::fabs(lo), std::fabs(hi));
    }
    bool contains(double v) const { return lo <= v && v <= hi; }
    bool contains_zero() const { return lo <= 0.0 && 0.0 <= hi; }
    bool is_point() const { return lo == hi; }
    bool is_empty() const { return !(lo <= hi); }

    Interval& operator+=(const Interval& b);
    Interval& operator-=(const Interval& b);
    Interval& operator*=(const Interval& b);
    Interval& operator/=(const Interval& b);
};

inline std::ostream& operator<<(std::ostream& out, const Interval& x) {
    return out << '[' << x.lo << ", " << x.hi << ']';
}

// Set operations (exact).
inline Interval hull(const Interval& a, const Interval& b) {
    return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)};
}
// Empty (lo > hi, see is_empty) when a and b do not meet.
inline Interval intersect(const Interval& a, const Interval& b) {
    return {std::max(a.lo, b.lo), std::min(a.hi, b.hi)};
}

// Arithmetic.

inline Interval operator-(const Interval& a) {
    return {-a.hi, -a.lo};
}

inline Interval operator+(const Interval& a, const Interval& b) {
    using namespace interval_detail;
    // Adding an exact zero is exact (sparse matrices add many).
    if (b.lo == 0.0 && b.hi == 0.0) return a;
    if (a.lo == 0.0 && a.hi == 0.0) return b;
    return {next_down(a.lo + b.lo), next_up(a.hi + b.hi)};
}

inline Interval operator-(const Interval& a, const Interval& b) {
    using namespace interval_detail;
    return {next_down(a.lo - b.hi), next_up(a.hi - b.lo)};
}

namespace interval_detail {

// std::fmin and std::fmax (a NaN argument is skipped), written inline: the
// library calls cost more than the products they sort.
inline double min_skipping_nan(double a, double b) {
    return (b < a || a != a) ? b : a;
}
inline double max_skipping_nan(double a, double b) {
    return (b > a || a != a) ? b : a;
}
inline double min4(double a, double b, double c, double d) {
    return min_skipping_nan(min_skipping_nan(a, b), min_skipping_nan(c, d));
}
inline double max4(double a, double b, double c, double d) {
    return max_skipping_nan(max_skipping_nan(a, b), max_skipping_nan(c, d));
}

// a * k for a finite non-zero point k: two products whose order is k's sign
// (the common case of a box times a constant matrix entry).
inline Interval scaled(const Interval& a, double k) {
    const double p = a.lo * k, q = a.hi * k;
    return k > 0.0 ? Interval{next_down(p), next_up(q)} : Interval{next_down(q), next_up(p)};
}

inline bool is_nonzero_point(const Interval& a) {
    return a.lo == a.hi && a.lo != 0.0 && std::isfinite(a.lo);
}

}  // namespace interval_detail

// m0 p0 + m1 p1 + m2 p2 in the order the double code forms it, with the term
// of a zero entry left out and that of a unit entry exact (as they are in
// the double code): most placements and frames are sparse, a translation or
// an axis-aligned frame, and skipping their zero products halves the cost
// of turning a box.
inline Interval sparse_dot(double m0, double m1, double m2, const std::array<Interval, 3>& p) {
    const double m[3] = {m0, m1, m2};
    Interval sum(0.0);
    for (int j = 0; j < 3; ++j) {
        if (m[j] == 0.0) continue;
        const Interval term = m[j] == 1.0    ? p[j]
                              : m[j] == -1.0 ? -p[j]
                                             : interval_detail::scaled(p[j], m[j]);
        sum = sum + term;
    }
    return sum;
}

inline Interval operator*(const Interval& a, const Interval& b) {
    using namespace interval_detail;
    // Exact cases first: a point 0 gives 0 (with an infinite end too, the
    // limit of finite products, as below) and a point 1 changes nothing.
    if ((b.lo == 0.0 && b.hi == 0.0) || (a.lo == 0.0 && a.hi == 0.0)) return Interval(0.0);
    if (b.lo == 1.0 && b.hi == 1.0) return a;
    if (a.lo == 1.0 && a.hi == 1.0) return b;
    if (is_nonzero_point(b)) return scaled(a, b.lo);
    if (is_nonzero_point(a)) return scaled(b, a.lo);
    // NaN products are skipped: 0 * inf at an end means the limit of finite
    // products, which the other three corners already bound.
    const double p1 = a.lo * b.lo, p2 = a.lo * b.hi, p3 = a.hi * b.lo, p4 = a.hi * b.hi;
    return {next_down(min4(p1, p2, p3, p4)), next_up(max4(p1, p2, p3, p4))};
}

inline Interval operator/(const Interval& a, const Interval& b) {
    using namespace interval_detail;
    if (b.contains_zero()) return Interval::entire();
    const double q1 = a.lo / b.lo, q2 = a.lo / b.hi, q3 = a.hi / b.lo, q4 = a.hi / b.hi;
    return {next_down(min4(q1, q2, q3, q4)), next_up(max4(q1, q2, q3, q4))};
}

inline Interval& Interval::operator+=(const Interval& b) {
    return *this = *this + b;
}
inline Interval& Interval::operator-=(const Interval& b) {
    return *this = *this - b;
}
inline Interval& Interval::operator*=(const Interval& b) {
    return *this = *this * b;
}
inline Interval& Interval::operator/=(const Interval& b) {
    return *this = *this / b;
}

// Exact functions (no rounding).

inline Interval abs(const Interval& a) {
    if (a.lo >= 0.0) return a;
    if (a.hi <= 0.0) return -a;
    return {0.0, std::max(-a.lo, a.hi)};
}
inline Interval min(const Interval& a, const Interval& b) {
    return {std::min(a.lo, b.lo), std::min(a.hi, b.hi)};
}
inline Interval max(const Interval& a, const Interval& b) {
    return {std::max(a.lo, b.lo), std::max(a.hi, b.hi)};
}
inline Interval floor(const Interval& a) {
    return {std::floor(a.lo), std::floor(a.hi)};
}
inline Interval ceil(const Interval& a) {
    return {std::ceil(a.lo), std::ceil(a.hi)};
}
inline Interval trunc(const Interval& a) {
    return {std::trunc(a.lo), std::trunc(a.hi)};
}

// Rounded functions.

inline Interval sqr(const Interval& a) {
    using namespace interval_detail;
    const double l = a.lo * a.lo, h = a.hi * a.hi;
    if (a.contains_zero()) return {0.0, next_up(std::max(l, h))};
    return {std::max(0.0, next_down(std::min(l, h))), next_up(std::max(l, h))};
}

// Negative parts are outside the domain and clamped to 0.
inline Interval sqrt(const Interval& a) {
    using namespace interval_detail;
    const double l = std::max(a.lo, 0.0), h = std::max(a.hi, 0.0);
    return {std::max(0.0, next_down(std::sqrt(l))), next_up(std::sqrt(h))};
}

inline Interval exp(const Interval& a) {
    using namespace interval_detail;
    return {std::max(0.0, down(std::exp(a.lo), kLibmUlps)), up(std::exp(a.hi), kLibmUlps)};
}

// Non-positive parts are clamped to 0, whose logarithm is -inf.
inline Interval log(const Interval& a) {
    using namespace interval_detail;
    const double l = std::max(a.lo, 0.0), h = std::max(a.hi, 0.0);
    return {down(std::log(l), kLibmUlps), up(std::log(h), kLibmUlps)};
}
inline Interval log10(const Interval& a) {
    using namespace interval_detail;
    const double l = std::max(a.lo, 0.0), h = std::max(a.hi, 0.0);
    return {down(std::log10(l), kLibmUlps), up(std::log10(h), kLibmUlps)};
}

inline Interval sin(const Interval& a) {
    using namespace interval_detail;
    if (a.lo == a.hi) {  // a point: libm reduces huge arguments exactly
        const double s = std::sin(a.lo);
        return {std::max(-1.0, down(s, kLibmUlps)), std::min(1.0, up(s, kLibmUlps))};
    }
    if (!(a.hi - a.lo < 2.0 * kPi)) return {-1.0, 1.0};
    const double s1 = std::sin(a.lo), s2 = std::sin(a.hi);
    double lo = std::max(-1.0, down(std::min(s1, s2), kLibmUlps));
    double hi = std::min(1.0, up(std::max(s1, s2), kLibmUlps));
    if (may_contain_periodic(a.lo, a.hi, 0.5 * kPi, 2.0 * kPi)) hi = 1.0;
    if (may_contain_periodic(a.lo, a.hi, 1.5 * kPi, 2.0 * kPi)) lo = -1.0;
    return {lo, hi};
}

inline Interval cos(const Interval& a) {
    using namespace interval_detail;
    if (a.lo == a.hi) {
        const double c = std::cos(a.lo);
        return {std::max(-1.0, down(c, kLibmUlps)), std::min(1.0, up(c, kLibmUlps))};
    }
    if (!(a.hi - a.lo < 2.0 * kPi)) return {-1.0, 1.0};
    const double c1 = std::cos(a.lo), c2 = std::cos(a.hi);
    double lo = std::max(-1.0, down(std::min(c1, c2), kLibmUlps));
    double hi = std::min(1.0, up(std::max(c1, c2), kLibmUlps));
    if (may_contain_periodic(a.lo, a.hi, 0.0, 2.0 * kPi)) hi = 1.0;
    if (may_contain_periodic(a.lo, a.hi, kPi, 2.0 * kPi)) lo = -1.0;
    return {lo, hi};
}

// entire() when a pole (pi/2 + k pi) may lie inside.
inline Interval tan(const Interval& a) {
    using namespace interval_detail;
    if (a.lo == a.hi) {
        const double t = std::tan(a.lo);
        return {down(t, kLibmUlps), up(t, kLibmUlps)};
    }
    if (!(a.hi - a.lo < kPi) || may_contain_periodic(a.lo, a.hi, 0.5 * kPi, kPi))
        return Interval::entire();
    return {down(std::tan(a.lo), kLibmUlps), up(std::tan(a.hi), kLibmUlps)};
}

// Arguments are clamped to the domain [-1, 1].
inline Interval asin(const Interval& a) {
    using namespace interval_detail;
    const double l = std::clamp(a.lo, -1.0, 1.0), h = std::clamp(a.hi, -1.0, 1.0);
    return {down(std::asin(l), kLibmUlps), up(std::asin(h), kLibmUlps)};
}
inline Interval acos(const Interval& a) {
    using namespace interval_detail;
    const double l = std::clamp(a.lo, -1.0, 1.0), h = std::clamp(a.hi, -1.0, 1.0);
    return {std::max(0.0, down(std::acos(h), kLibmUlps)), up(std::acos(l), kLibmUlps)};
}
inline Interval atan(const Interval& a) {
    using namespace interval_detail;
    return {down(std::atan(a.lo), kLibmUlps), up(std::atan(a.hi), kLibmUlps)};
}

// The angle of (x, y) in [-pi, pi]. Over a box that holds the origin or
// meets the cut along the negative x axis (where +0 and -0 give pi and -pi)
// the whole circle; elsewhere the angle is continuous on the box, and its
// extremes lie at corners.
inline Interval atan2(const Interval& y, const Interval& x) {
    using namespace interval_detail;
    const double pi_up = next_up(kPi);
    if (y.contains_zero() && x.lo <= 0.0) return {-pi_up, pi_up};
    const double a1 = std::atan2(y.lo, x.lo), a2 = std::atan2(y.lo, x.hi);
    const double a3 = std::atan2(y.hi, x.lo), a4 = std::atan2(y.hi, x.hi);
    return {std::max(-pi_up, down(std::min(std::min(a1, a2), std::min(a3, a4)), kLibmUlps)),
            std::min(pi_up, up(std::max(std::max(a1, a2), std::max(a3, a4)), kLibmUlps))};
}

namespace interval_detail {

// x^n for a whole number n, tight: even powers are not negative.
inline Interval integer_power(const Interval& x, double n) {
    if (n == 0.0) return {1.0, 1.0};
    const bool even = std::fmod(n, 2.0) == 0.0;
    const double pl = std::pow(x.lo, n), ph = std::pow(x.hi, n);
    if (n > 0.0) {
        if (!even) return {down(pl, kLibmUlps), up(ph, kLibmUlps)};
        if (x.contains_zero()) return {0.0, up(std::max(pl, ph), kLibmUlps)};
        return {std::max(0.0, down(std::min(pl, ph), kLibmUlps)), up(std::max(pl, ph), kLibmUlps)};
    }
    // Negative powers: a pole at 0.
    if (x.contains_zero()) {
        if (!even) return Interval::entire();
        const double m = std::pow(x.magnitude(), n);
        return {std::max(0.0, down(m, kLibmUlps)), kInf};
    }
    if (!even) return {down(ph, kLibmUlps), up(pl, kLibmUlps)};
    return {std::max(0.0, down(std::min(pl, ph), kLibmUlps)), up(std::max(pl, ph), kLibmUlps)};
}

// x^y over a box with x >= 0: x^y is monotone in x for each y and in y for
// each x (also along x = 0, where it falls from inf through 1 to 0), so its
// extremes lie at corners.
inline Interval nonnegative_power(double xl, double xh, const Interval& y) {
    const double c1 = std::pow(xl, y.lo), c2 = std::pow(xl, y.hi);
    const double c3 = std::pow(xh, y.lo), c4 = std::pow(xh, y.hi);
    return {std::max(0.0, down(std::min(std::min(c1, c2), std::min(c3, c4)), kLibmUlps)),
            up(std::max(std::max(c1, c2), std::max(c3, c4)), kLibmUlps)};
}

}  // namespace interval_detail

// std::pow's meaning: negative bases have values only at whole exponents.
inline Interval pow(const Interval& x, const Interval& y) {
    using namespace interval_detail;
    if (y.lo == y.hi && std::isfinite(y.lo) && std::trunc(y.lo) == y.lo)
        return integer_power(x, y.lo);
    if (x.lo >= 0.0) return nonnegative_power(x.lo, x.hi, y);
    // Some bases are negative. The non-negative ones as usual ...
    Interval r = x.hi >= 0.0 ? nonnegative_power(0.0, x.hi, y) : Interval(0.0);
    const bool whole_exponent_inside = std::ceil(y.lo) <= std::floor(y.hi);
    if (x.hi < 0.0 && !whole_exponent_inside) return r;  // nothing in the domain: clamped to 0
    // ... and the negative ones give +-|x|^n at whole n, bounded by the
    // largest |x|^y over the box.
    if (whole_exponent_inside) {
        const double mag_lo = x.hi >= 0.0 ? 0.0 : -x.hi;
        const Interval m = nonnegative_power(mag_lo, -x.lo, y);
        r = hull(r, Interval(-m.hi, m.hi));
    }
    return r;
}

// An axis-aligned box as three intervals (x, y, z): what interval
// evaluation of a point gives and what a motion's world_box takes.
using IntervalBox = std::array<Interval, 3>;

}  // namespace hexant::runtime
