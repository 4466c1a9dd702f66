// first_non_finite: the instants where a time function is NaN or infinite,
// found by interval search and confirmed by the point value, and none where
// an interval only might hold one.
#include "runtime/time/non_finite.hpp"

#include <cmath>

#include <catch2/catch.hpp>

#include "runtime/time/time_function.hpp"

using hexant::runtime::first_non_finite;
using hexant::runtime::TimeFunction;
using hexant::runtime::TimeOp;

namespace {

const TimeFunction t = TimeFunction::clock();

TimeFunction sqrt_of(const TimeFunction& f) {
    return TimeFunction::apply(TimeOp::Sqrt, f);
}

}  // namespace

TEST_CASE("constants: NaN and infinities at the first instant, numbers never", "[non_finite]") {
    CHECK(first_non_finite(TimeFunction(std::nan("")), 0.0, 1.0) == 0.0);
    CHECK(first_non_finite(TimeFunction(-HUGE_VAL), 2.0, 3.0) == 2.0);
    CHECK_FALSE(first_non_finite(TimeFunction(1e308), 0.0, 1.0));
}

TEST_CASE("a function of time: the first instant found, its point value not finite",
          "[non_finite]") {
    // NaN from the start: sqrt of a negative.
    CHECK(first_non_finite(sqrt_of(t - 0.5), 0.0, 1.0) == 0.0);
    // NaN after the middle: the interval evaluator clamps sqrt's argument
    // into its domain, so only the domain test sees it; the first double
    // past 0.5 is the instant.
    const TimeFunction late = sqrt_of(TimeFunction(0.5) - t);
    const auto found = first_non_finite(late, 0.0, 1.0);
    REQUIRE(found);
    CHECK(*found == std::nextafter(0.5, 1.0));
    CHECK(std::isnan(late(*found)));
    // An infinity at one instant: 1 / (t - 0.3) at the double 0.3.
    const TimeFunction pole = TimeFunction(1.0) / (t - 0.3);
    const auto at = first_non_finite(pole, 0.0, 1.0);
    REQUIRE(at);
    CHECK(std::isinf(pole(*at)));
    CHECK(*at == 0.3);
    // Outside the time searched there is nothing to find.
    CHECK_FALSE(first_non_finite(pole, 0.4, 1.0));
    CHECK_FALSE(first_non_finite(late, 0.0, 0.5));
}

TEST_CASE("an interval that could hold an infinity where no point does is not one",
          "[non_finite]") {
    // t - t is [-1, 1] as an interval over [0, 1], so 1 / (t - t + 1) might
    // divide by zero for all the intervals know; every point gives 1.
    CHECK_FALSE(first_non_finite(TimeFunction(1.0) / (t - t + 1.0), 0.0, 1.0));
    // sqrt(t - t): the argument's interval dips below 0, its points never.
    CHECK_FALSE(first_non_finite(sqrt_of(t - t), 0.0, 1.0));
    // A fast tan has poles near many instants but none at a double.
    CHECK_FALSE(first_non_finite(TimeFunction::apply(TimeOp::Tan, t * 1000.0), 0.0, 1.0));
}
