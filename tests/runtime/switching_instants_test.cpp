// Switching instants (runtime/time/switching_instants.hpp) are exact: on each
// side of an instant the point evaluator gives the truth its piece says,
// so the instant sits between two neighbouring doubles where the double
// evaluation of the condition changes; for a continuous condition that is
// within a few ulps of the exact root. And lifetimes (runtime/time/lifetime.hpp)
// hold every double of a split exactly once.
#include "runtime/time/switching_instants.hpp"

#include <cmath>

#include <catch2/catch.hpp>

#include "runtime/time/lifetime.hpp"
#include "runtime/time/time_ops.hpp"

namespace rt = hexant::runtime;
using rt::TimeFunction;
using rt::TimeOp;

namespace {

const TimeFunction t = TimeFunction::clock();

double before(double x) {
    return rt::interval_detail::next_down(x);
}

// Every instant is a switch of the point evaluator's truth, and the pieces
// agree with it at their ends and middles.
void check_exact(const TimeFunction& c, const rt::TruthPieces& p, const rt::Interval& range) {
    for (const double s : p.instants) {
        INFO("instant " << s);
        CHECK(rt::pov_true(c(before(s))) != rt::pov_true(c(s)));
        CHECK(p.when_true.contains(s) == rt::pov_true(c(s)));
        CHECK(p.when_false.contains(before(s)) == !rt::pov_true(c(before(s))));
    }
    for (const auto& piece : p.when_true.within(range)) {
        CHECK(rt::pov_true(c(piece.lo)));
        CHECK(rt::pov_true(c(piece.hi)));
        CHECK(rt::pov_true(c(piece.mid())));
    }
    for (const auto& piece : p.when_false.within(range)) {
        CHECK_FALSE(rt::pov_true(c(piece.lo)));
        CHECK_FALSE(rt::pov_true(c(piece.hi)));
        CHECK_FALSE(rt::pov_true(c(piece.mid())));
    }
}

double ulps_apart(double a, double b) {
    return std::fabs(a - b) / std::fabs(std::nextafter(b, 2 * b) - b);
}

}  // namespace

TEST_CASE("clock*10 > 3.1415 switches once, at the root to a few ulps", "[runtime][switching]") {
    const TimeFunction c = TimeFunction::apply(TimeOp::Greater, t * 10.0, 3.1415);
    const rt::Interval range(0.0, 1.0);
    const rt::TruthPieces p = rt::split_by_truth(c, {range}, 10000);
    REQUIRE(p.instants.size() == 1);
    CHECK(ulps_apart(p.instants[0], 0.31415) <= 4.0);
    CHECK(p.when_false.contains(0.0));
    CHECK(p.when_true.contains(1.0));
    check_exact(c, p, range);
}

TEST_CASE("sin(2*pi*clock) > 0.5 holds between 1/12 and 5/12", "[runtime][switching]") {
    const TimeFunction c = TimeFunction::apply(
        TimeOp::Greater, TimeFunction::apply(TimeOp::Sin, t * (2.0 * M_PI)), 0.5);
    const rt::Interval range(0.0, 1.0);
    const rt::TruthPieces p = rt::split_by_truth(c, {range}, 10000);
    REQUIRE(p.instants.size() == 2);
    // sin's slope at the roots is large: the double roots lie within a few
    // ulps of the exact ones (libm's sin is within 1 ulp).
    CHECK(ulps_apart(p.instants[0], 1.0 / 12.0) <= 8.0);
    CHECK(ulps_apart(p.instants[1], 5.0 / 12.0) <= 8.0);
    check_exact(c, p, range);
}

TEST_CASE("vlength(C) != 0 is false only within POV-Ray's epsilon of the zero",
          "[runtime][switching]") {
    // C = <clock - 0.5, 0, 0>: |C| != 0 is false where |clock - 0.5| < 1e-10.
    const TimeFunction x = t - 0.5;
    const TimeFunction length = TimeFunction::apply(TimeOp::Sqrt, x * x);
    const TimeFunction c = TimeFunction::apply(TimeOp::NotEqual, length, 0.0);
    const rt::Interval range(0.0, 1.0);
    const rt::TruthPieces p = rt::split_by_truth(c, {range}, 10000);
    REQUIRE(p.instants.size() == 2);
    CHECK(std::fabs(p.instants[0] - (0.5 - 1e-10)) < 1e-15);
    CHECK(std::fabs(p.instants[1] - (0.5 + 1e-10)) < 1e-15);
    CHECK(p.when_false.contains(0.5));
    check_exact(c, p, range);
}

TEST_CASE("a step function switches at its jumps exactly", "[runtime][switching]") {
    // mod(floor(clock * 4), 2) = 1: true on [0.25, 0.5) and [0.75, 1).
    const TimeFunction step = TimeFunction::apply(TimeOp::Floor, t * 4.0);
    const TimeFunction c =
        TimeFunction::apply(TimeOp::Equal, TimeFunction::apply(TimeOp::Mod, step, 2.0), 1.0);
    const rt::Interval range(0.0, 1.0);
    const rt::TruthPieces p = rt::split_by_truth(c, {range}, 10000);
    REQUIRE(p.instants.size() == 4);
    CHECK(p.instants[0] == 0.25);
    CHECK(p.instants[1] == 0.5);
    CHECK(p.instants[2] == 0.75);
    CHECK(p.instants[3] == 1.0);
    check_exact(c, p, range);
    // div(floor(clock * 4), 2) = 1: on [0.5, 1).
    const TimeFunction half =
        TimeFunction::apply(TimeOp::Equal, TimeFunction::apply(TimeOp::IntDiv, step, 2.0), 1.0);
    const rt::TruthPieces q = rt::split_by_truth(half, {range}, 10000);
    REQUIRE(q.instants.size() == 2);
    CHECK(q.instants[0] == 0.5);
    CHECK(q.instants[1] == 1.0);
    check_exact(half, q, range);
}

TEST_CASE("a step near clock 0, where doubles are dense, is decided", "[runtime][switching]") {
    // int(2 + 3 * clock) from 0: the sum is within an ulp of 2 for some
    // 2^60 doubles below 1e-16; the range of point values there is exactly
    // 2 (point_range.hpp), so the piece is decided whole instead of halved
    // without end.
    const TimeFunction step = TimeFunction::apply(TimeOp::Int, 2.0 + t * 3.0);
    const auto pieces = rt::split_by_value(step, {{0.0, 1.0}}, 10000);
    REQUIRE(pieces.size() == 4);
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        CHECK(pieces[i].value == 2.0 + static_cast<double>(i));
        CHECK(step(pieces[i].time.lo) == pieces[i].value);
        CHECK(step(pieces[i].time.hi) == pieces[i].value);
        if (i > 0) CHECK(step(before(pieces[i].time.lo)) == pieces[i - 1].value);
    }
    // 10 - 10 * clock is exactly 10 in doubles for clock below about
    // 9e-17, and below 10 in reals: the range of point values
    // (point_range.hpp) decides the first piece, [0, 8.9e-17].
    const TimeFunction down = TimeFunction::apply(TimeOp::Int, 10.0 - t * 10.0);
    const auto countdown = rt::split_by_value(down, {{0.0, 1.0}}, 10000);
    REQUIRE(countdown.size() == 11);
    CHECK(countdown[0].value == 10.0);
    CHECK(countdown[0].time.hi < 1e-16);
    CHECK(down(countdown[0].time.hi) == 10.0);
    CHECK(down(countdown[1].time.lo) == 9.0);
    // Keys of several functions at once (str()'s text, chr()'s code).
    const rt::KeyOf key = [](std::size_t which, double v) {
        return which == 0 ? std::to_string(static_cast<long long>(std::floor(v * 2)))
                          : std::to_string(static_cast<long long>(std::trunc(v)));
    };
    const auto keyed = rt::split_by_key({t, 2.0 + t * 3.0}, {{0.0, 0.9}}, 10000, key);
    // Cuts at 1/3, 1/2 and 2/3 (doubles next to them).
    REQUIRE(keyed.size() == 4);
    CHECK(keyed[2].time.lo == 0.5);
    CHECK(std::trunc(2.0 + keyed[1].time.lo * 3.0) == 3.0);
    CHECK(std::trunc(2.0 + before(keyed[1].time.lo) * 3.0) == 2.0);
}

TEST_CASE("a split covers its domain, pieces in several intervals", "[runtime][switching]") {
    const TimeFunction c = TimeFunction::apply(TimeOp::Less, t, 0.6);
    const std::vector<rt::Interval> domain{{0.0, 0.2}, {0.5, 0.7}};
    const rt::TruthPieces p = rt::split_by_truth(c, domain, 10000);
    REQUIRE(p.instants.size() == 1);
    CHECK(p.instants[0] == 0.6);
    CHECK(p.when_true.within({0.0, 1.0}).size() == 2);
    CHECK(p.when_false.within({0.0, 1.0}).size() == 1);
    CHECK_FALSE(p.when_true.contains(0.3));
    CHECK_FALSE(p.when_false.contains(0.3));
    CHECK(p.when_true.contains(before(0.6)));
    CHECK(p.when_false.contains(0.6));
}

TEST_CASE("a condition that flickers without end is refused, not sampled", "[runtime][switching]") {
    const TimeFunction c = TimeFunction::apply(
        TimeOp::Greater, TimeFunction::apply(TimeOp::Sin, 1.0 / (t - 0.5)), 0.0);
    CHECK_THROWS_AS(rt::split_by_truth(c, {{0.0, 1.0}}, 10000), rt::LimitError);
    // A finite number of switches past the limit is refused too.
    const TimeFunction many = TimeFunction::apply(
        TimeOp::Greater, TimeFunction::apply(TimeOp::Sin, t * 200.0 * M_PI), 0.0);
    CHECK_THROWS_AS(rt::split_by_truth(many, {{0.0, 1.0}}, 100), rt::LimitError);
    CHECK(rt::split_by_truth(many, {{0.0, 1.0}}, 1000).instants.size() >= 199);
}

TEST_CASE("lifetimes: sets of closed intervals of doubles", "[runtime][switching]") {
    const rt::Lifetime a = rt::Lifetime::of({{0.5, 1.0}, {0.0, 0.25}, {0.2, 0.3}});
    REQUIRE(a.pieces().size() == 2);
    CHECK(a.pieces()[0].hi == 0.3);
    CHECK(a.contains(0.3));
    CHECK_FALSE(a.contains(0.4));
    CHECK(a.holds_all({0.5, 0.9}));
    CHECK_FALSE(a.holds_all({0.2, 0.6}));
    CHECK(a.meets({0.35, 0.5}));
    CHECK_FALSE(a.meets({0.31, 0.49}));
    // Touching at neighbouring doubles: one piece.
    CHECK(rt::Lifetime::of({{0.0, before(0.5)}, {0.5, 1.0}}).pieces().size() == 1);
    // The complement holds every other double.
    const rt::Lifetime rest = a.complement_within({0.0, 1.0});
    CHECK(rest.contains(0.4));
    CHECK(rest.contains(rt::interval_detail::next_up(0.3)));
    CHECK_FALSE(rest.contains(0.3));
    CHECK(rest.intersect(a).is_never());
    CHECK(rt::Lifetime::always().intersect(a) == a);
}
