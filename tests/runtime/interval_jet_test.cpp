// Interval jets (runtime/time/interval_jet.hpp): over random intervals of time,
// each expression's double value must lie in v, its derivative (Dual, at a
// point) in d, its second derivative (a difference quotient of Dual
// derivatives, which equals f'' somewhere between) in dd, and the double
// value within r of a long double evaluation; steps, kinks and choices are
// smooth exactly where they cannot change.
#include "runtime/time/interval_jet.hpp"

#include <cmath>
#include <random>

#include <catch2/catch.hpp>

#include "runtime/time/dual.hpp"

namespace rt = hexant::runtime;

namespace {

// Each written once for every number type, in the same order of operations.
template <class N>
N wave(const N& t) {
    using std::cos;
    using std::sin;
    return sin(t * N(3.0)) * (t * t) + cos(t);
}
template <class N>
N ratio(const N& t) {
    using std::exp;
    return exp(t) / (N(1.0) + t * t);
}
template <class N>
N root(const N& t) {
    using std::sqrt;
    return sqrt(N(1.0) + t * t) * N(2.5) - t;
}
template <class N>
N power(const N& t) {
    using std::pow;
    return pow(N(3.0) + t, N(2.5));
}
// A swarm sphere's x: 5 cos(w t) - 0.3 sin(w t) after a tilt.
template <class N>
N orbit(const N& t) {
    using std::cos;
    using std::sin;
    const N angle = (N(37.0) + N(1440.0) * t) * N(0.017453292519943295);
    return cos(angle) * N(5.0) * N(0.866) - sin(angle) * N(0.3);
}

template <class N>
N value(int which, const N& t) {
    switch (which) {
        case 0:
            return wave(t);
        case 1:
            return ratio(t);
        case 2:
            return root(t);
        case 3:
            return power(t);
        default:
            return orbit(t);
    }
}

bool within(double x, const rt::Interval& i, double slack) {
    return x >= i.lo - slack && x <= i.hi + slack;
}

}  // namespace

TEST_CASE("an interval jet holds the value, both derivatives and the rounding", "[interval][jet]") {
    std::mt19937_64 random(2026);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int which = 0; which < 5; ++which) {
        for (int trial = 0; trial < 300; ++trial) {
            const double width = std::pow(10.0, -6.0 + 6.0 * unit(random));
            const double lo = -2.0 + 3.9 * unit(random);
            const rt::Interval t(lo, lo + width);
            const rt::IntervalJet jet = value(which, rt::IntervalJet::variable(t));
            INFO("expression " << which << " over " << t);
            REQUIRE(jet.smooth());
            for (int k = 0; k < 20; ++k) {
                const double x = t.lo + (t.hi - t.lo) * unit(random);
                const double v = value(which, x);
                CHECK(within(v, jet.v, 0.0));
                const double exact = double(value(which, (long double)x));
                // long double's own error is about 2^-11 of double's.
                CHECK(std::fabs(v - exact) <=
                      jet.r + 1e-3 * std::fabs(jet.r) + 1e-18 * std::fabs(exact));
                const rt::Dual dual = value(which, rt::Dual::variable(x));
                CHECK(within(dual.d, jet.d, 1e-12 * (1.0 + jet.d.magnitude())));
                // f'(x + h) - f'(x) = h f''(xi) for some xi between.
                const double h = std::min(1e-4, t.hi - x);
                if (h > 1e-7) {
                    const rt::Dual ahead = value(which, rt::Dual::variable(x + h));
                    const double second = (ahead.d - dual.d) / ((x + h) - x);
                    const double rounding = 4e-16 * (std::fabs(ahead.d) + std::fabs(dual.d)) / h;
                    CHECK(within(second, jet.dd, rounding + 1e-9 * jet.dd.magnitude()));
                }
            }
        }
    }
}

TEST_CASE("interval jets: smooth where a step, kink or choice cannot change", "[interval][jet]") {
    const auto at = [](double lo, double hi) {
        return rt::IntervalJet::variable(rt::Interval(lo, hi));
    };
    using rt::TimeOp;
    // floor is constant inside (0.2, 0.8), and jumps at 1.
    const rt::IntervalJet inside = rt::apply_op(TimeOp::Floor, at(0.2, 0.8));
    CHECK(inside.smooth());
    CHECK(inside.v.lo == 0.0);
    CHECK(inside.dd.magnitude() == 0.0);
    CHECK_FALSE(rt::apply_op(TimeOp::Floor, at(0.9, 1.1)).smooth());
    // abs has a corner at 0.
    CHECK(rt::apply_op(TimeOp::Abs, at(0.1, 0.5)).smooth());
    CHECK_FALSE(rt::apply_op(TimeOp::Abs, at(-0.1, 0.5)).smooth());
    // A choice decided throughout takes its branch's derivatives.
    const rt::IntervalJet c =
        rt::apply_op(TimeOp::Conditional, rt::apply_op(TimeOp::Less, at(0.0, 0.3), 0.4),
                     at(0.0, 0.3) * at(0.0, 0.3), 2.0);
    CHECK(c.smooth());
    CHECK(c.dd.lo == 2.0);
    CHECK_FALSE(
        rt::apply_op(TimeOp::Conditional, rt::apply_op(TimeOp::Less, at(0.0, 0.5), 0.4), 1.0, 2.0)
            .smooth());
    // No derivative worked out: not smooth, value still held.
    const rt::IntervalJet a = rt::apply_op(TimeOp::Atan, at(0.0, 1.0));
    CHECK_FALSE(a.smooth());
    CHECK(a.v.contains(std::atan(0.5)));
}
