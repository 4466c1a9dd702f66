// Small pieces of careful floating point arithmetic that the shape routines
// share: products without cancellation, an overflow-free length, and the
// numerically stable pair of quadratic roots (Ray Tracing Gems, ch. 7).
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

namespace hexant::runtime::geometry {

inline constexpr double kEpsilon = 0x1p-52;  // the spacing of doubles at 1

// a*b - c*d within 2 ulps of the exact value (Kahan's algorithm with fma;
// Jeannerod, Louvet and Muller 2013). In particular its sign is exact and it
// is zero exactly when a*b == c*d, which makes edge tests watertight.
inline double difference_of_products(double a, double b, double c, double d) {
    const double cd = c * d;
    const double error = std::fma(-c, d, cd);  // cd - c*d, exactly
    return std::fma(a, b, -cd) + error;
}

// c - dot(a, b) as if computed in twice the precision, then rounded
// (Ogita, Rump and Oishi's Dot2 with fma): the products' rounding errors and
// the sums' are carried along exactly. For a point a far from the origin,
// dot(a, b) is large and c - dot(a, b) small; plain evaluation would lose
// the digits of the large terms.
inline double compensated_offset(double c, const glm::dvec3& a, const glm::dvec3& b) {
    double sum = c, error = 0.0;
    for (int k = 0; k < 3; ++k) {
        const double product = -a[k] * b[k];
        const double product_error = std::fma(-a[k], b[k], -product);  // exact
        const double next = sum + product;
        const double z = next - sum;
        error += (sum - (next - z)) + (product - z) + product_error;  // two-sum, exact
        sum = next;
    }
    return sum + error;
}

// A number as an unevaluated sum hi + lo (|lo| <= ulp(hi) / 2): about 106
// bits, for the few places where a small result must be formed from large
// terms (error-free transformations: Knuth's two-sum, fma's two-product).
struct DoubleDouble {
    double hi, lo;
    double value() const { return hi + lo; }
};

inline DoubleDouble two_sum(double a, double b) {
    const double s = a + b;
    const double z = s - a;
    return {s, (a - (s - z)) + (b - z)};
}

inline DoubleDouble two_product(double a, double b) {
    const double p = a * b;
    return {p, std::fma(a, b, -p)};
}

inline DoubleDouble operator+(const DoubleDouble& a, const DoubleDouble& b) {
    const DoubleDouble s = two_sum(a.hi, b.hi);
    return two_sum(s.hi, s.lo + a.lo + b.lo);
}

inline DoubleDouble operator-(const DoubleDouble& a) {
    return {-a.hi, -a.lo};
}

inline DoubleDouble operator*(const DoubleDouble& a, const DoubleDouble& b) {
    const DoubleDouble p = two_product(a.hi, b.hi);
    return two_sum(p.hi, p.lo + (a.hi * b.lo + a.lo * b.hi));
}

// x*x - y*y for x, y >= 0 as (x - y)(x + y): the difference of two squares of
// nearly equal numbers loses all digits; this form loses none beyond x and y.
inline double difference_of_squares(double x, double y) {
    return (x - y) * (x + y);
}

// |v| without overflow or underflow in the squares.
inline double safe_length(const glm::dvec3& v) {
    // The usual case first: squares far from both ends of the range lose
    // nothing (their sum keeps full relative precision).
    const double squared = glm::dot(v, v);
    if (squared > 0x1p-900 && squared < 0x1p900) return std::sqrt(squared);
    const double m = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
    if (!(m > 0.0) || !std::isfinite(m)) return m == 0.0 ? 0.0 : m;
    const glm::dvec3 w = v / m;
    return m * std::sqrt(glm::dot(w, w));
}

inline double max_abs(const glm::dvec3& v) {
    return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
}

// The real roots of A t^2 + 2 B t + C = 0 given disc = B^2 - A C, computed by
// the caller in a form without cancellation. The pair C/q, q/A with
// q = -(B + sign(B) sqrt(disc)) never subtracts nearly equal numbers
// (Ray Tracing Gems ch. 7, "the stable pair"). A may be zero (one root) or
// negative (a cone's two nappes). Roots come sorted; infinite ones dropped.
struct QuadraticRoots {
    int count = 0;
    double t[2] = {0.0, 0.0};
};

inline QuadraticRoots solve_quadratic(double A, double B, double C, double disc) {
    QuadraticRoots roots;
    if (!(disc >= 0.0)) return roots;  // also rejects NaN
    const double q = -(B + std::copysign(std::sqrt(disc), B));
    auto add = [&roots](double t) {
        if (std::isfinite(t)) roots.t[roots.count++] = t;
    };
    if (q == 0.0) {
        // B = 0 and disc = 0, so A C = 0: a double root at 0 if A != 0.
        if (A != 0.0) add(0.0);
        return roots;
    }
    add(C / q);
    if (A != 0.0) add(q / A);
    if (roots.count == 2 && roots.t[0] > roots.t[1]) std::swap(roots.t[0], roots.t[1]);
    return roots;
}

}  // namespace hexant::runtime::geometry
