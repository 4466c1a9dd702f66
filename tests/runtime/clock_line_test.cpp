// Lines in clock (runtime/time/clock_line.hpp) against the tapes they stand in
// for: every form the language builds gives the tape's value bit for bit at
// points, over intervals, with derivatives and as interval jets; anything
// else is not taken for a line.
#include "runtime/time/clock_line.hpp"

#include <vector>

#include <catch2/catch.hpp>

#include "runtime/time/time_tape.hpp"
#include "same_bits.hpp"

using hexant::runtime::ClockLine;
using hexant::runtime::Dual;
using hexant::runtime::Interval;
using hexant::runtime::IntervalJet;
using hexant::runtime::TimeFunction;
using hexant::runtime::TimeOp;
using hexant::runtime::TimeTape;
using hexant::test::same_bits;

namespace {

template <class N>
N on_tape(const TimeTape& tape, const N& t) {
    N out;
    tape.evaluate(t, &out);
    return out;
}

}  // namespace

TEST_CASE("a line in clock evaluates as its tape does, bit for bit", "[clock_line]") {
    const TimeFunction t = TimeFunction::clock();
    // Constants that round differently in each order, and the signs of zero.
    const double a = 0.1 * 3.0, k = 360.0 / 7.0;
    const std::vector<TimeFunction> lines = {
        t,
        t * k,
        TimeFunction(k) * t,
        t / k,
        t + a,
        TimeFunction(a) + t,
        t - a,
        TimeFunction(a) - t,
        TimeFunction(a) + TimeFunction(k) * t,
        t * k + a,
        TimeFunction(a) - t / k,
        t * k - a,
        TimeFunction(-0.0) + t * -1.0,
        TimeFunction(1e300) * t + 1e300,
    };
    for (const TimeFunction& f : lines) {
        INFO(f.to_string());
        const auto line = ClockLine::of(f);
        REQUIRE(line);
        CHECK_FALSE(line->is_constant());
        const TimeTape tape = TimeTape::compile({f});
        for (const double x : {0.0, -0.0, 0.25, 1.0 / 3.0, 1.0, -7.5, 1e-310, 1e308}) {
            INFO("t = " << x);
            CHECK(same_bits(line->at(x), f(x)));
            CHECK(same_bits(line->at(x), on_tape(tape, x)));
            const Dual dl = line->at(Dual::variable(x)), dt = on_tape(tape, Dual::variable(x));
            CHECK(same_bits(dl.v, dt.v));
            CHECK(same_bits(dl.d, dt.d));
        }
        for (const Interval& x : {Interval(0.0, 1.0), Interval(0.25, 0.5), Interval(-3.0, 1e-3)}) {
            CHECK(same_bits(line->at(x), on_tape(tape, x)));
            const IntervalJet jl = line->at(IntervalJet::variable(x));
            const IntervalJet jt = on_tape(tape, IntervalJet::variable(x));
            CHECK(same_bits(jl.v, jt.v));
            CHECK(same_bits(jl.d, jt.d));
            CHECK(same_bits(jl.dd, jt.dd));
            CHECK(same_bits(jl.r, jt.r));
        }
    }
}

TEST_CASE("only constants and lines in clock are taken for lines", "[clock_line]") {
    const TimeFunction t = TimeFunction::clock();
    const auto constant = ClockLine::of(TimeFunction(2.5));
    REQUIRE(constant);
    CHECK(constant->is_constant());
    CHECK(constant->constant_value() == 2.5);
    CHECK(constant->at(0.7) == 2.5);
    for (const TimeFunction& f : {t * t, TimeFunction(2.0) / t, t + t, -t, t * 2.0 * 3.0,
                                  (t + 1.0) * 2.0, TimeFunction::apply(TimeOp::Sin, t), t * 2.0 + t,
                                  TimeFunction(1.0) + (TimeFunction(2.0) + t)}) {
        INFO(f.to_string());
        CHECK_FALSE(ClockLine::of(f));
    }
}
