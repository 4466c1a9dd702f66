#include "runtime/geometry/polynomial_roots.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace hexant::runtime::geometry {

namespace {

constexpr double kUnit = 0x1p-53;  // unit roundoff
constexpr int kCapacity = kMaxPolynomialDegree + 1;

constexpr double gamma(int n) {
    return n * kUnit / (1.0 - n * kUnit);
}

// A polynomial with double-double coefficients hi[i] + lo[i] (the original
// has lo = 0; derivatives keep i * c_i exactly), of degree n, hi[n] != 0.
struct Poly {
    int n = -1;
    double hi[kCapacity] = {};
    double lo[kCapacity] = {};
};

struct TwoTerms {
    double s, e;
};

TwoTerms two_sum(double a, double b) {
    const double s = a + b;
    const double z = s - a;
    return {s, (a - (s - z)) + (b - z)};
}

TwoTerms two_product(double a, double b) {
    const double p = a * b;
    return {p, std::fma(a, b, -p)};
}

// Drops leading zeros and scales by a power of two (exact) so that the
// largest |hi| lies in [0.5, 1): no overflow for |x| within range_limit(n).
void normalize(Poly& p) {
    while (p.n >= 0 && p.hi[p.n] == 0.0 && p.lo[p.n] == 0.0) --p.n;
    if (p.n < 0) return;
    // (A zero hi with a nonzero lo cannot happen: lo is below ulp(hi) / 2.)
    double largest = 0.0;
    for (int i = 0; i <= p.n; ++i) largest = std::max(largest, std::fabs(p.hi[i]));
    int exponent = 0;
    std::frexp(largest, &exponent);
    for (int i = 0; i <= p.n; ++i) {
        p.hi[i] = std::ldexp(p.hi[i], -exponent);
        p.lo[i] = std::ldexp(p.lo[i], -exponent);
    }
}

Poly derivative(const Poly& p) {
    Poly d;
    d.n = p.n - 1;
    for (int i = 1; i <= p.n; ++i) {
        const TwoTerms product = two_product(static_cast<double>(i), p.hi[i]);
        const TwoTerms sum = two_sum(product.s, product.e + static_cast<double>(i) * p.lo[i]);
        d.hi[i - 1] = sum.s;
        d.lo[i - 1] = sum.e;
    }
    normalize(d);
    return d;
}

// Where |x|^n times the (normalized) coefficients' sum stays far below
// overflow.
double range_limit(int n) {
    if (n <= 0) return std::numeric_limits<double>::max();
    return std::pow(std::numeric_limits<double>::max() / (8.0 * (n + 1)), 1.0 / n) * 0.5;
}

// Compensated Horner (Graillat, Langlois and Louvet, "Compensated Horner
// scheme", 2005) with the lo parts folded into the correction term. The
// error-free transformations make p(x) = s + e(x) exactly, e the polynomial
// of the products' and sums' rounding errors (plus the lo parts); the only
// errors are those of evaluating e by Horner, bounded by gamma(4n + 4) times
// the running magnitude of its terms (a dynamic bound: where the transforms
// are exact, as next to a cluster of roots, it is tiny), the lo parts' own
// rounding (a derivative's i * lo), the final rounding, and underflow in the
// error-free products (an absolute term).
PolynomialValue evaluate(const Poly& p, double x) {
    if (p.n < 0) return {0.0, 0.0};
    double s = p.hi[p.n];
    double correction = p.lo[p.n];
    double terms = std::fabs(p.lo[p.n]);  // Horner of |e's terms| at |x|
    double underflow = 0.0;
    const double ax = std::fabs(x);
    for (int i = p.n - 1; i >= 0; --i) {
        const TwoTerms product = two_product(s, x);
        const TwoTerms sum = two_sum(product.s, p.hi[i]);
        s = sum.s;
        const double term = product.e + sum.e + p.lo[i];
        correction = correction * x + term;
        terms = terms * ax + std::fabs(product.e) + std::fabs(sum.e) + std::fabs(p.lo[i]);
        underflow = underflow * ax + 0x1p-1070;
    }
    const double value = s + correction;
    const int n = std::max(p.n, 1);
    const double bound =
        (2.0 * kUnit * std::fabs(value) + gamma(4 * n + 4) * terms + underflow) * (1.0 + gamma(4));
    return {value, bound};
}

int sign_of(const PolynomialValue& v) {
    if (std::fabs(v.value) <= v.bound) return 0;
    return v.value > 0.0 ? 1 : -1;
}

// p'(x) in plain double (Newton steps only).
double slope(const Poly& p, double x) {
    if (p.n < 1) return 0.0;
    double value = p.hi[p.n], d = 0.0;
    for (int i = p.n - 1; i >= 0; --i) {
        d = d * x + value;
        value = value * x + p.hi[i];
    }
    return d;
}

// Doubles in the order of their values as integers, for halving a bracket
// by the count of doubles in it (at most 64 halvings to adjacent doubles).
std::int64_t ordered_key(double x) {
    const std::int64_t bits = std::bit_cast<std::int64_t>(x);
    return bits < 0 ? std::numeric_limits<std::int64_t>::min() - bits : bits;
}

double from_key(std::int64_t key) {
    const std::int64_t bits = key < 0 ? std::numeric_limits<std::int64_t>::min() - key : key;
    return std::bit_cast<double>(bits);
}

double middle_double(double l, double r) {
    if (l < 0.0 && r > 0.0) return 0.0;
    if (l == 0.0) l = 0.0;  // -0 and +0 share a key
    if (r == 0.0) r = 0.0;
    const std::int64_t a = ordered_key(l), b = ordered_key(r);
    const std::int64_t mid =
        a + static_cast<std::int64_t>(
                (static_cast<std::uint64_t>(b) - static_cast<std::uint64_t>(a)) / 2);
    return from_key(mid);
}

// The one root of p in (l, r), where p is monotone and the signs at the ends
// are certain and opposite (sl at l).
double bracketed_root(const Poly& p, double l, double r, int sl, double vl, double vr) {
    double x = l - vl * ((r - l) / (vr - vl));  // the secant through the ends
    if (!(x > l && x < r)) x = middle_double(l, r);
    double width_before = r - l, width_two_before = 2.0 * (r - l);
    for (int iteration = 0; iteration < 400; ++iteration) {
        // Within rounding of zero the computed sign is still the likeliest:
        // it goes on narrowing the bracket, which already holds the root.
        const PolynomialValue v = evaluate(p, x);
        if (v.value == 0.0) return x + 0.0;  // (no -0)
        const int s = v.value > 0.0 ? 1 : -1;
        if (s == sl) {
            l = x;
            vl = v.value;
        } else {
            r = x;
            vr = v.value;
        }
        if (std::nextafter(l, r) >= r) break;  // adjacent doubles
        const double width = r - l;
        const double d = slope(p, x);
        const double newton = d != 0.0 ? x - v.value / d : std::numeric_limits<double>::quiet_NaN();
        const bool shrinking = width <= 0.5 * width_two_before;
        width_two_before = width_before;
        width_before = width;
        x = newton > l && newton < r && shrinking ? newton : middle_double(l, r);
    }
    return (std::fabs(vl) <= std::fabs(vr) ? l : r) + 0.0;
}

// The roots of p in [a, b] (a <= b), ascending and distinct, appended to out.
int solve(const Poly& p, double a, double b, double* out) {
    if (p.n < 1) return 0;
    // Breakpoints: the ends and the critical points between them.
    double xs[kCapacity + 1];
    int m = 0;
    xs[m++] = a;
    if (p.n >= 2 && a < b) {
        double critical[kCapacity];
        const int count = solve(derivative(p), a, b, critical);
        for (int i = 0; i < count; ++i)
            if (critical[i] > xs[m - 1] && critical[i] < b) xs[m++] = critical[i];
    }
    if (b > xs[m - 1]) xs[m++] = b;
    PolynomialValue values[kCapacity + 1];
    int signs[kCapacity + 1];
    for (int i = 0; i < m; ++i) {
        values[i] = evaluate(p, xs[i]);
        signs[i] = sign_of(values[i]);
    }
    int count = 0;
    auto add = [&](double x) {
        if (count == 0 || x > out[count - 1]) out[count++] = x;
    };
    for (int i = 0; i < m; ++i) {
        if (signs[i] == 0) {
            // A run of breakpoints at which p is zero within rounding: one
            // (multiple or clustered) root, where |p| is least.
            int j = i, least = i;
            while (j + 1 < m && signs[j + 1] == 0) {
                ++j;
                if (std::fabs(values[j].value) < std::fabs(values[least].value)) least = j;
            }
            add(xs[least]);
            i = j;
            continue;
        }
        if (i + 1 < m && signs[i + 1] != 0 && signs[i + 1] != signs[i])
            add(bracketed_root(p, xs[i], xs[i + 1], signs[i], values[i].value,
                               values[i + 1].value));
    }
    return count;
}

}  // namespace

PolynomialValue evaluate_polynomial(std::span<const double> coefficients, double x) {
    Poly p;
    p.n = static_cast<int>(std::min<std::size_t>(coefficients.size(), kCapacity)) - 1;
    for (int i = 0; i <= p.n; ++i) p.hi[i] = coefficients[i];
    while (p.n >= 0 && p.hi[p.n] == 0.0) --p.n;
    return evaluate(p, x);
}

PolynomialRoots polynomial_roots(std::span<const double> coefficients, double lo, double hi) {
    PolynomialRoots roots;
    if (std::isnan(lo) || std::isnan(hi) || !(lo <= hi)) return roots;
    int n = static_cast<int>(coefficients.size()) - 1;
    for (const double c : coefficients)
        if (!std::isfinite(c)) return roots;
    while (n >= 0 && coefficients[n] == 0.0) --n;
    if (n < 1 || n > kMaxPolynomialDegree) return roots;
    // Lines, and quadratics whose roots are well apart (discriminant above
    // 1e-8 of b^2: the stable formula's roots are then good to a few ulps):
    // closed forms, a hundred times faster than the isolation below, which
    // takes the rest (near-double roots).
    if (n == 1) {
        const double x = -coefficients[0] / coefficients[1];
        if (std::isfinite(x) && x >= lo && x <= hi) roots.root[roots.count++] = x;
        return roots;
    }
    if (n == 2) {
        const double a2 = coefficients[2], b1 = coefficients[1], c0 = coefficients[0];
        const double disc =
            std::fma(b1, b1, -4.0 * a2 * c0) + std::fma(-4.0 * a2, c0, 4.0 * a2 * c0);
        if (std::isfinite(disc) && disc > 1e-8 * b1 * b1 && b1 != 0.0) {
            const double q = -0.5 * (b1 + std::copysign(std::sqrt(disc), b1));
            double x1 = q / a2, x2 = c0 / q;
            if (x1 > x2) std::swap(x1, x2);
            for (const double x : {x1, x2})
                if (std::isfinite(x) && x >= lo && x <= hi &&
                    (roots.count == 0 || x != roots.root[0]))
                    roots.root[roots.count++] = x;
            return roots;
        }
    }
    Poly p;
    p.n = n;
    for (int i = 0; i <= n; ++i) p.hi[i] = coefficients[i];
    normalize(p);
    // Cauchy's bound: every root has |x| <= 1 + max |c_i / c_n|.
    double ratio = 0.0;
    for (int i = 0; i < n; ++i) ratio = std::max(ratio, std::fabs(p.hi[i]));
    ratio /= std::fabs(p.hi[n]);
    const double reach = std::min((1.0 + ratio) * (1.0 + 1e-12), range_limit(n));
    const double a = std::max(lo, -reach), b = std::min(hi, reach);
    if (!(a <= b)) return roots;
    double found[kCapacity];
    roots.count = solve(p, a, b, found);
    std::sort(found, found + roots.count);
    for (int i = 0; i < roots.count; ++i) roots.root[i] = found[i];
    return roots;
}

}  // namespace hexant::runtime::geometry
