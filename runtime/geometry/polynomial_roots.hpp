// The real roots of a polynomial of modest degree (up to kMaxPolynomialDegree)
// in a closed interval [lo, hi], sorted ascending: the solver the spline
// shapes share (lathe: degree 2, 4 or 6 per segment; sor: 3), in place of
// POV-Ray's polysolv.cpp (closed forms for degrees 2 to 4, Sturm sequences
// with the `sturm` flag).
//
// Method: recursive derivative bracketing. The roots of p' (found the same
// way, down to degree 1) split [lo, hi] into pieces on which p is monotone;
// a piece whose ends have opposite signs holds exactly one root, found by
// safeguarded Newton (a step is taken only when it stays inside the
// shrinking bracket and the bracket keeps halving; otherwise the bracket is
// halved in the ordering of doubles, so at most 64 halvings reach adjacent
// doubles). A multiple root is a critical point at which p is zero within
// its evaluation's rounding bound. Every sign is taken from compensated
// Horner evaluation (Graillat, Langlois, Louvet 2005: as accurate as Horner
// in twice the working precision) with its a-priori error bound, and the
// derivatives' coefficients are carried exactly as double-double, so a sign
// is trusted only where it is certain, and "zero" means "within rounding".
//
// Accuracy: a simple root is returned within a few ulps (1 in the tests) of
// the exact root of the polynomial whose coefficients are the given
// doubles. Signs are resolved as in twice the precision, so a cluster of m
// roots is separated when it is wider than about u^(2/m) of the roots' size
// (u = 2^-53: about 1e-16 for a pair, 1e-11 for three, 1e-8 for four);
// a narrower cluster, and a true multiple root, is reported once, at the
// critical point where |p| is least (exactly, for exact multiple roots such
// as (x - 1)^2 or (x - 1)^3 written with exact coefficients). Roots come
// sorted and distinct. Never NaN or Inf for finite coefficients; any
// non-finite coefficient or bound (but an infinite lo or hi) gives no
// roots, as does the zero polynomial and a constant.
// Leading zero coefficients lower the degree. Roots larger in magnitude than
// the Cauchy bound cannot exist; beyond about (DBL_MAX / 8n)^(1/n) (1e51 for
// degree 6) they are not reported (the polynomial would overflow there).
#pragma once

#include <array>
#include <span>

namespace hexant::runtime::geometry {

inline constexpr int kMaxPolynomialDegree = 16;

struct PolynomialRoots {
    int count = 0;
    std::array<double, kMaxPolynomialDegree> root{};

    const double* begin() const { return root.data(); }
    const double* end() const { return root.data() + count; }
};

// coefficients[i] multiplies x^i (ascending order: c0 + c1 x + ... + cn x^n;
// POV-Ray's Solve_Polynomial takes them descending). More than
// kMaxPolynomialDegree + 1 coefficients (after dropping leading zeros): no roots.
PolynomialRoots polynomial_roots(std::span<const double> coefficients, double lo, double hi);

// p(x) by compensated Horner, with a bound on |value - p(x)| (p(x) the exact
// value of the polynomial with these double coefficients at the double x):
// the sign of value is certain when |value| > bound.
struct PolynomialValue {
    double value = 0.0;
    double bound = 0.0;
};
PolynomialValue evaluate_polynomial(std::span<const double> coefficients, double x);

}  // namespace hexant::runtime::geometry
