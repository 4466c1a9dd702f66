// The shared polynomial root solver: exact references where the
// coefficients are exact (double, triple and nearly double roots, roots a
// ulp apart), 113-bit (__float128) references for rounded coefficients,
// coefficients over hundreds of decades, and random polynomials whose every
// sign change on a fine grid (evaluated in __float128) must hold a reported
// root, and whose every reported root must be a sign change or a zero of
// the 113-bit polynomial within a few ulps.
#include "runtime/geometry/polynomial_roots.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <catch2/catch.hpp>

using hexant::runtime::geometry::evaluate_polynomial;
using hexant::runtime::geometry::polynomial_roots;
using hexant::runtime::geometry::PolynomialRoots;

namespace {

using Quad = __float128;

// Coefficients (ascending) of prod (x - r_i), in double: exact when the
// products are.
std::vector<double> from_roots(const std::vector<double>& roots) {
    std::vector<double> c{1.0};
    for (const double r : roots) {
        std::vector<double> next(c.size() + 1, 0.0);
        for (std::size_t i = 0; i < c.size(); ++i) {
            next[i + 1] += c[i];
            next[i] -= r * c[i];
        }
        c = next;
    }
    return c;
}

// The same product in __float128, to check that the double one is exact.
std::vector<Quad> from_roots_quad(const std::vector<double>& roots) {
    std::vector<Quad> c{1};
    for (const double r : roots) {
        std::vector<Quad> next(c.size() + 1, 0);
        for (std::size_t i = 0; i < c.size(); ++i) {
            next[i + 1] += c[i];
            next[i] -= Quad(r) * c[i];
        }
        c = next;
    }
    return c;
}

Quad eval_quad(const std::vector<double>& c, Quad x) {
    Quad v = 0;
    for (std::size_t i = c.size(); i-- > 0;) v = v * x + Quad(c[i]);
    return v;
}

Quad eval_quad_slope(const std::vector<double>& c, Quad x) {
    Quad v = 0;
    for (std::size_t i = c.size(); i-- > 1;) v = v * x + Quad(c[i]) * Quad(static_cast<double>(i));
    return v;
}

// The root of the double polynomial near a nominal simple root, by Newton
// in __float128.
double quad_root_near(const std::vector<double>& c, double nominal) {
    Quad x = nominal;
    for (int i = 0; i < 100; ++i) x -= eval_quad(c, x) / eval_quad_slope(c, x);
    return static_cast<double>(x);
}

double ulps_apart(double a, double b) {
    return std::fabs(a - b) / std::max(std::nextafter(std::fabs(b), 1e308) - std::fabs(b),
                                       std::numeric_limits<double>::denorm_min());
}

std::vector<double> roots_of(const std::vector<double>& c, double lo, double hi) {
    const PolynomialRoots r = polynomial_roots(c, lo, hi);
    return {r.begin(), r.end()};
}

}  // namespace

TEST_CASE("polynomial roots: exact simple roots of every degree", "[polynomial]") {
    for (int degree = 1; degree <= 10; ++degree) {
        std::vector<double> roots;
        for (int i = 0; i < degree; ++i) roots.push_back(-2.0 + 0.5 * i);
        const auto c = from_roots(roots);
        const auto found = roots_of(c, -10.0, 10.0);
        INFO("degree " << degree);
        REQUIRE(found.size() == roots.size());
        for (std::size_t i = 0; i < roots.size(); ++i) CHECK(found[i] == roots[i]);
    }
}

TEST_CASE("polynomial roots: double and triple roots, exact coefficients", "[polynomial]") {
    // (x - 1)^2 (x - 2): one double root, reported once, exactly.
    CHECK(roots_of(from_roots({1.0, 1.0, 2.0}), -5.0, 5.0) == std::vector<double>{1.0, 2.0});
    // (x - 1)^3, (x - 0.75)^3 (x + 3)^2, (x - 0.5)^4 (x + 0.25)^2.
    CHECK(roots_of(from_roots({1.0, 1.0, 1.0}), -5.0, 5.0) == std::vector<double>{1.0});
    CHECK(roots_of(from_roots({0.75, 0.75, 0.75, -3.0, -3.0}), -5.0, 5.0) ==
          std::vector<double>{-3.0, 0.75});
    CHECK(roots_of(from_roots({0.5, 0.5, 0.5, 0.5, -0.25, -0.25}), -5.0, 5.0) ==
          std::vector<double>{-0.25, 0.5});
    // A double root at an end of the interval, and just outside it.
    CHECK(roots_of(from_roots({1.0, 1.0, 3.0}), 1.0, 2.0) == std::vector<double>{1.0});
    CHECK(roots_of(from_roots({1.0, 1.0, 3.0}), -1.0, 1.0) == std::vector<double>{1.0});
    CHECK(roots_of(from_roots({1.0, 1.0, 3.0}), 1.5, 2.0).empty());
    // Double root at zero; a double root next to a simple one.
    CHECK(roots_of(from_roots({0.0, 0.0, 0.375}), -1.0, 1.0) == std::vector<double>{0.0, 0.375});
    // A double root with no real neighbour: (x - 0.5)^2 (x^2 + 1).
    std::vector<double> c = from_roots({0.5, 0.5});
    std::vector<double> with_complex(c.size() + 2, 0.0);
    for (std::size_t i = 0; i < c.size(); ++i) {
        with_complex[i] += c[i];
        with_complex[i + 2] += c[i];
    }
    CHECK(roots_of(with_complex, -10.0, 10.0) == std::vector<double>{0.5});
}

TEST_CASE("polynomial roots: nearly double roots with exact coefficients", "[polynomial]") {
    // (x - 1)(x - 1 - e) for e down to 4 ulps of 1 (closer, -(2 + e) rounds
    // and the roots of the polynomial given are complex): both roots, exactly.
    for (const int k : {10, 20, 30, 40, 45, 50}) {
        const double e = std::ldexp(1.0, -k);
        const auto c = from_roots({1.0, 1.0 + e});
        const auto exact = from_roots_quad({1.0, 1.0 + e});
        for (int i = 0; i < 3; ++i) REQUIRE(exact[i] == Quad(c[i]));
        INFO("e = 2^-" << k);
        const auto found = roots_of(c, 0.0, 2.0);
        REQUIRE(found.size() == 2);
        CHECK(ulps_apart(found[0], 1.0) <= 1.0);
        CHECK(ulps_apart(found[1], 1.0 + e) <= 1.0);
    }
    // (x - 1)^2 (x - 1 - 2^-30): a double and a simple root 1e-9 apart.
    const double e = std::ldexp(1.0, -30);
    const auto c = from_roots({1.0, 1.0, 1.0 + e});
    for (int i = 0; i < 4; ++i) REQUIRE(from_roots_quad({1.0, 1.0, 1.0 + e})[i] == Quad(c[i]));
    const auto found = roots_of(c, 0.0, 2.0);
    REQUIRE(found.size() == 2);
    CHECK(found[0] == 1.0);
    // Its slope there is e^2 = 1e-18, and values are resolved to about 1e-31:
    // the root to about 1e-13 (in fact 69 ulps, 1.5e-14).
    CHECK(std::fabs(found[1] - (1.0 + e)) <= 1e-13);
    // Closer than 2x precision resolves (the values near the pair are 1e-37,
    // their rounding bound 1e-31): one root for the cluster, at the double root.
    const double g = std::ldexp(1.0, -40);
    CHECK(roots_of(from_roots({1.0, 1.0, 1.0 + g}), 0.0, 2.0) == std::vector<double>{1.0});
    // Three simple roots 2^-20 apart.
    const double f = std::ldexp(1.0, -20);
    CHECK(roots_of(from_roots({1.0 - f, 1.0, 1.0 + f}), 0.0, 2.0) ==
          std::vector<double>{1.0 - f, 1.0, 1.0 + f});
}

TEST_CASE("polynomial roots: (x - 1)(x - 1 - 1e-9) with rounded coefficients", "[polynomial]") {
    const double r2 = 1.0 + 1e-9;
    const std::vector<double> c{r2, -(1.0 + r2), 1.0};  // rounded as a scene would round them
    // The roots of the rounded polynomial, by the quadratic formula in 113 bits.
    const Quad b = c[1], a = c[2], cc = c[0];
    const Quad disc = b * b - 4 * a * cc;
    REQUIRE(disc > 0);
    Quad sq = 0;
    {  // sqrt by Newton in __float128
        sq = std::sqrt(static_cast<double>(disc));
        for (int i = 0; i < 10; ++i) sq = 0.5 * (sq + disc / sq);
    }
    const double lo = static_cast<double>((-b - sq) / (2 * a));
    const double hi = static_cast<double>((-b + sq) / (2 * a));
    const auto found = roots_of(c, 0.0, 2.0);
    REQUIRE(found.size() == 2);
    CHECK(ulps_apart(found[0], lo) <= 2.0);
    CHECK(ulps_apart(found[1], hi) <= 2.0);
    // Within rounding of the intended roots.
    CHECK(std::fabs(found[0] - 1.0) < 1e-15);
    CHECK(std::fabs(found[1] - r2) < 1e-15);
}

TEST_CASE("polynomial roots: wide coefficient ranges", "[polynomial]") {
    // Roots over 18 decades: the coefficients are rounded; the reference is
    // the rounded polynomial's roots in 113 bits.
    const std::vector<double> nominal{-3e8, -1e-9, 2.5e-3, 1.0, 7e5, 4e9};
    const auto c = from_roots(nominal);
    const auto found = roots_of(c, -1e12, 1e12);
    REQUIRE(found.size() == nominal.size());
    for (std::size_t i = 0; i < nominal.size(); ++i) {
        const double reference = quad_root_near(c, nominal[i]);
        INFO("root " << nominal[i] << " found " << found[i] << " reference " << reference);
        CHECK(ulps_apart(found[i], reference) <= 4.0);
    }
    // Scaled by 2^-1000 and 2^600: the same roots.
    for (const int e : {-1000, 600}) {
        std::vector<double> scaled = c;
        for (double& x : scaled) x = std::ldexp(x, e);
        CHECK(roots_of(scaled, -1e12, 1e12) == found);
    }
    // A tiny leading coefficient: roots near 1 and -1e20.
    const auto tiny = roots_of({-1.0, 1.0, 1e-20}, -1e30, 1e30);
    REQUIRE(tiny.size() == 2);
    CHECK(std::fabs(tiny[0] / -1e20 - 1.0) < 1e-14);
    CHECK(std::fabs(tiny[1] - 1.0) < 1e-15);
    // Leading zeros lower the degree; constants and zero have no roots.
    CHECK(roots_of({-2.0, 1.0, 0.0, 0.0}, -5.0, 5.0) == std::vector<double>{2.0});
    CHECK(roots_of({3.0}, -5.0, 5.0).empty());
    CHECK(roots_of({0.0, 0.0}, -5.0, 5.0).empty());
}

TEST_CASE("polynomial roots: never NaN or Inf, empty for bad input", "[polynomial]") {
    const double inf = std::numeric_limits<double>::infinity();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK(roots_of({1.0, nan, 1.0}, -1.0, 1.0).empty());
    CHECK(roots_of({1.0, inf, 1.0}, -1.0, 1.0).empty());
    CHECK(roots_of({-1.0, 0.0, 1.0}, nan, 1.0).empty());
    CHECK(roots_of({-1.0, 0.0, 1.0}, 1.0, -1.0).empty());
    // Infinite ends are clipped to where roots can be.
    CHECK(roots_of({-1.0, 0.0, 1.0}, -inf, inf) == std::vector<double>{-1.0, 1.0});
    // Extreme magnitudes.
    std::mt19937_64 engine(7);
    std::uniform_real_distribution<double> exponent(-300.0, 300.0), mantissa(-1.0, 1.0);
    for (int trial = 0; trial < 20000; ++trial) {
        std::vector<double> c(1 + trial % 7);
        for (double& x : c) x = mantissa(engine) * std::pow(10.0, exponent(engine));
        const auto found = roots_of(c, -inf, inf);
        for (std::size_t i = 0; i < found.size(); ++i) {
            REQUIRE(std::isfinite(found[i]));
            if (i > 0) REQUIRE(found[i] > found[i - 1]);
        }
    }
}

TEST_CASE("polynomial roots: random polynomials against a 113-bit sign scan", "[polynomial]") {
    std::mt19937_64 engine(12345);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int checked_roots = 0;
    for (int trial = 0; trial < 400; ++trial) {
        const int degree = 2 + trial % 5;
        std::vector<double> c;
        if (trial % 2 == 0) {
            // Random roots in [-1, 1], some in close pairs, times random quadratics.
            std::vector<double> roots;
            for (int i = 0; i < degree; ++i) {
                if (i > 0 && trial % 3 == 0 && i % 2 == 1)
                    roots.push_back(roots.back() +
                                    std::pow(10.0, -3.0 - 10.0 * (unit(engine) + 1.0) / 2.0));
                else
                    roots.push_back(unit(engine));
            }
            c = from_roots(roots);
        } else {
            for (int i = 0; i <= degree; ++i) c.push_back(unit(engine));
        }
        const double lo = -1.5, hi = 1.5;
        const auto found = roots_of(c, lo, hi);
        // Every reported root: a sign change of the exact polynomial within a
        // few ulps, or an exact polynomial value within the rounding bound.
        for (const double x : found) {
            const double step = 4.0 * (std::nextafter(std::fabs(x), 2.0) - std::fabs(x)) + 1e-300;
            const Quad left = eval_quad(c, Quad(x) - step), right = eval_quad(c, Quad(x) + step);
            const bool changes = (left <= 0 && right >= 0) || (left >= 0 && right <= 0);
            const double bound = evaluate_polynomial(c, x).bound;
            const bool small = std::fabs(static_cast<double>(eval_quad(c, x))) <= 2.0 * bound;
            INFO("trial " << trial << " root " << x);
            CHECK((changes || small));
        }
        // Every sign change on a fine grid holds a reported root.
        const int n = 4000;
        Quad previous = eval_quad(c, Quad(lo));
        for (int i = 1; i <= n; ++i) {
            const double x0 = lo + (hi - lo) * (i - 1) / n, x1 = lo + (hi - lo) * i / n;
            const Quad v = eval_quad(c, Quad(x1));
            if ((previous < 0 && v > 0) || (previous > 0 && v < 0)) {
                const bool held = std::any_of(found.begin(), found.end(), [&](double r) {
                    return r >= x0 - 1e-15 && r <= x1 + 1e-15;
                });
                INFO("trial " << trial << " sign change in [" << x0 << ", " << x1 << "]");
                CHECK(held);
                ++checked_roots;
            }
            previous = v;
        }
    }
    CHECK(checked_roots > 500);
}
