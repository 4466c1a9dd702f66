// Dual numbers: a value and its first derivative with respect to one
// parameter (time), for root finding. Each operation computes the value with
// exactly the expression the double evaluator uses, so the value part of a
// Dual evaluation equals the point evaluation bit for bit; the derivative
// follows the chain rule. Where a function has no derivative (floor, ceil,
// trunc jumps, abs at 0, min/max ties) the derivative of the branch the value
// took is used; the step functions have derivative 0.
//
// The free functions are found by argument-dependent lookup, so templates can
// write `using std::sin; sin(x)` for double, Interval and Dual alike.
#pragma once

#include <cmath>
#include <ostream>

namespace hexant::runtime {

struct Dual {
    double v, d;  // value, derivative

    Dual(double value = 0.0, double derivative = 0.0)  // NOLINT: implicit, numbers are constants
        : v(value), d(derivative) {}

    // The independent variable at a value: derivative 1.
    static Dual variable(double value) { return {value, 1.0}; }

    Dual& operator+=(const Dual& b);
    Dual& operator-=(const Dual& b);
    Dual& operator*=(const Dual& b);
    Dual& operator/=(const Dual& b);
};

inline std::ostream& operator<<(std::ostream& out, const Dual& x) {
    return out << '(' << x.v << ", d " << x.d << ')';
}

inline Dual operator-(const Dual& a) {
    return {-a.v, -a.d};
}
inline Dual operator+(const Dual& a, const Dual& b) {
    return {a.v + b.v, a.d + b.d};
}
inline Dual operator-(const Dual& a, const Dual& b) {
    return {a.v - b.v, a.d - b.d};
}
inline Dual operator*(const Dual& a, const Dual& b) {
    return {a.v * b.v, a.d * b.v + a.v * b.d};
}
inline Dual operator/(const Dual& a, const Dual& b) {
    const double q = a.v / b.v;
    return {q, (a.d - q * b.d) / b.v};
}

inline Dual& Dual::operator+=(const Dual& b) {
    return *this = *this + b;
}
inline Dual& Dual::operator-=(const Dual& b) {
    return *this = *this - b;
}
inline Dual& Dual::operator*=(const Dual& b) {
    return *this = *this * b;
}
inline Dual& Dual::operator/=(const Dual& b) {
    return *this = *this / b;
}

inline Dual sqr(const Dual& a) {
    return {a.v * a.v, 2.0 * a.v * a.d};
}
inline Dual sqrt(const Dual& a) {
    const double r = std::sqrt(a.v);
    return {r, a.d / (2.0 * r)};
}
inline Dual abs(const Dual& a) {
    return {std::fabs(a.v), a.v < 0.0 ? -a.d : a.d};
}
// POV-Ray's min and max: a < b ? a : b, a > b ? a : b.
inline Dual min(const Dual& a, const Dual& b) {
    return a.v < b.v ? a : b;
}
inline Dual max(const Dual& a, const Dual& b) {
    return a.v > b.v ? a : b;
}

inline Dual sin(const Dual& a) {
    return {std::sin(a.v), std::cos(a.v) * a.d};
}
inline Dual cos(const Dual& a) {
    return {std::cos(a.v), -std::sin(a.v) * a.d};
}
inline Dual tan(const Dual& a) {
    const double t = std::tan(a.v);
    return {t, (1.0 + t * t) * a.d};
}
inline Dual asin(const Dual& a) {
    return {std::asin(a.v), a.d / std::sqrt(1.0 - a.v * a.v)};
}
inline Dual acos(const Dual& a) {
    return {std::acos(a.v), -a.d / std::sqrt(1.0 - a.v * a.v)};
}
inline Dual atan(const Dual& a) {
    return {std::atan(a.v), a.d / (1.0 + a.v * a.v)};
}
inline Dual atan2(const Dual& y, const Dual& x) {
    return {std::atan2(y.v, x.v), (x.v * y.d - y.v * x.d) / (x.v * x.v + y.v * y.v)};
}

inline Dual exp(const Dual& a) {
    const double e = std::exp(a.v);
    return {e, e * a.d};
}
inline Dual log(const Dual& a) {
    return {std::log(a.v), a.d / a.v};
}
inline Dual log10(const Dual& a) {
    constexpr double ln10 = 2.30258509299404568402;
    return {std::log10(a.v), a.d / (a.v * ln10)};
}

// d(x^y) = y x^(y-1) dx + x^y ln(x) dy; each term only when its derivative is
// not zero, so that constant exponents of negative bases and constant bases
// of 0 stay finite.
inline Dual pow(const Dual& x, const Dual& y) {
    const double p = std::pow(x.v, y.v);
    double d = 0.0;
    if (x.d != 0.0) d += y.v * std::pow(x.v, y.v - 1.0) * x.d;
    if (y.d != 0.0) d += p * std::log(x.v) * y.d;
    return {p, d};
}

inline Dual floor(const Dual& a) {
    return {std::floor(a.v), 0.0};
}
inline Dual ceil(const Dual& a) {
    return {std::ceil(a.v), 0.0};
}
inline Dual trunc(const Dual& a) {
    return {std::trunc(a.v), 0.0};
}

}  // namespace hexant::runtime
