// Time functions through every operation: folding of constants, symbolic
// functions of clock, and POV-Ray's meaning of each operator.
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include <catch2/catch.hpp>

#include "runtime/motion/spline.hpp"
#include "runtime/time/time_function.hpp"
#include "runtime/time/time_ops.hpp"

using hexant::runtime::apply_op;
using hexant::runtime::arity;
using hexant::runtime::TimeFunction;
using hexant::runtime::TimeOp;

namespace {

// Arguments that are valid for every operation (asin/acos/log/sqrt ...).
double argument(int i, double t) {
    return 0.3 + 0.2 * i + 0.1 * t;
}

}  // namespace

TEST_CASE("every operation folds constants and evaluates symbolically alike", "[time]") {
    for (int k = static_cast<int>(TimeOp::Negate); k <= static_cast<int>(TimeOp::Conditional);
         ++k) {
        const TimeOp op = static_cast<TimeOp>(k);
        INFO(hexant::runtime::name(op));
        const int n = arity(op);
        REQUIRE(n >= 1);
        REQUIRE(n <= 3);
        // Constants in, a constant out, equal to apply_op.
        const double a = argument(0, 0.0), b = argument(1, 0.0), c = argument(2, 0.0);
        const TimeFunction folded = n == 1   ? TimeFunction::apply(op, a)
                                    : n == 2 ? TimeFunction::apply(op, a, b)
                                             : TimeFunction::apply(op, a, b, c);
        CHECK(folded.is_constant());
        CHECK(folded.constant() == apply_op(op, a, b, c));
        // Clock in: a function of time that matches apply_op at every t.
        const TimeFunction t = TimeFunction::clock();
        const TimeFunction x = t * 0.1 + 0.3, y = t * 0.1 + 0.5, z = t * 0.1 + 0.7;
        const TimeFunction f = n == 1   ? TimeFunction::apply(op, x)
                               : n == 2 ? TimeFunction::apply(op, x, y)
                                        : TimeFunction::apply(op, x, y, z);
        CHECK(f.depends_on_time());
        for (double time : {0.0, 0.25, 0.5, 1.0, 2.5}) {
            const double want =
                apply_op(op, argument(0, time), argument(1, time), argument(2, time));
            const double got = f(time);
            CHECK(got == Approx(want).margin(1e-12));
        }
    }
}

TEST_CASE("POV-Ray's comparisons and truth", "[time]") {
    CHECK(apply_op(TimeOp::Equal, 1.0, 1.0 + 1e-11) == 1.0);  // = has a tolerance
    CHECK(apply_op(TimeOp::Equal, 1.0, 1.0 + 1e-9) == 0.0);
    CHECK(apply_op(TimeOp::NotEqual, 1.0, 1.0 + 1e-11) == 0.0);
    CHECK(apply_op(TimeOp::Less, 1.0, 1.0 + 1e-11) == 1.0);  // < has none
    CHECK(apply_op(TimeOp::Not, 0.5) == 0.0);
    CHECK(apply_op(TimeOp::And, 1.0, 1e-11) == 0.0);
    CHECK(apply_op(TimeOp::Or, 0.0, -2.0) == 1.0);
    CHECK(apply_op(TimeOp::Int, -1.5) == -1.0);  // int truncates
    CHECK(apply_op(TimeOp::Floor, -1.5) == -2.0);
    CHECK(apply_op(TimeOp::Mod, -7.0, 3.0) == -1.0);  // fmod's sign
    CHECK(apply_op(TimeOp::IntDiv, -7.0, 2.0) == -3.0);
    CHECK(apply_op(TimeOp::Log10, 100.0) == Approx(2.0));
    CHECK(apply_op(TimeOp::Select, -1.0, 5.0, 6.0) == 5.0);
    CHECK(apply_op(TimeOp::Select, 0.0, 5.0, 6.0) == 6.0);
}

TEST_CASE("a branch not taken is not evaluated", "[time]") {
    const TimeFunction t = TimeFunction::clock();
    // sqrt(-1 - t) is NaN for every t >= 0; it lies on the branch not taken.
    const TimeFunction nan_side = TimeFunction::apply(TimeOp::Sqrt, -t - 1.0);
    const TimeFunction f = TimeFunction::apply(TimeOp::Conditional, t - 10.0, nan_side, t * 2.0);
    // t - 10 is true (non-zero) for t = 0.5, so that takes the NaN side; 10 takes the other.
    CHECK(std::isnan(f(0.5)));
    CHECK(f(10.0) == 20.0);
    const TimeFunction g = TimeFunction::apply(TimeOp::Select, t - 1.0, t, nan_side);
    CHECK(g(0.5) == 0.5);
}

TEST_CASE("constant conditions pick their branch at once", "[time]") {
    const TimeFunction t = TimeFunction::clock();
    CHECK_FALSE(TimeFunction::apply(TimeOp::Conditional, 1.0, t, 2.0).is_constant());
    CHECK(TimeFunction::apply(TimeOp::Conditional, 0.0, t, 2.0).is_constant());
    CHECK(TimeFunction::apply(TimeOp::Select, -1.0, 3.0, t).constant() == 3.0);
}

TEST_CASE("a product with a constant zero is the constant zero", "[time]") {
    // `y * clock` is <0 * clock, clock, 0 * clock>: its zero components are
    // no functions of time (a motion then evaluates one angle, not three).
    const TimeFunction f = TimeFunction::clock() + 1.0;
    CHECK((TimeFunction(0.0) * f).is_constant());
    CHECK((f * TimeFunction(0.0)).is_constant());
    CHECK((f * TimeFunction(0.0)).constant() == 0.0);
    CHECK_FALSE((TimeFunction(1e-300) * f).is_constant());
    CHECK_FALSE((TimeFunction(0.0) / f).is_constant());  // 0 / 0 is not 0
}

TEST_CASE("time functions read back as text", "[time]") {
    const TimeFunction f = TimeFunction::clock() * 360.0;
    CHECK(f.to_string().find("clock") != std::string::npos);
    CHECK(TimeFunction(2.5).to_string() == "2.5");
}

TEST_CASE("a spline of clock evaluates the spline at each time", "[time]") {
    using hexant::runtime::Spline;
    auto spline = std::make_shared<Spline>(
        hexant::runtime::SplineKind::Linear,
        std::vector<Spline::Key>{{0.0, {0, 10, 0, 0, 0}}, {1.0, {2, 20, 0, 0, 0}}}, 2);
    const TimeFunction y = TimeFunction::spline_component(spline, 1, TimeFunction::clock() * 0.5);
    CHECK(y.depends_on_time());
    CHECK(y(1.0) == Approx(15.0));
    CHECK(TimeFunction::spline_component(spline, 0, 0.5).constant() == Approx(1.0));
}

// A time function is a double or a node boxed in a NaN (time_function.hpp):
// every double must come back as itself, a NaN whose bits read as a boxed
// node must stay a constant, and copies must share and free nodes rightly
// (the sanitized suite, `make sanitize`, checks the freeing).
TEST_CASE("a time function holds any double, and counts its node's owners", "[time]") {
    const double values[] = {0.0, -0.0, 1.5, -1e308, 5e-324, HUGE_VAL, -HUGE_VAL};
    for (const double v : values) {
        const TimeFunction f(v);
        REQUIRE(f.is_constant());
        CHECK(std::bit_cast<std::uint64_t>(f.constant()) == std::bit_cast<std::uint64_t>(v));
    }
    // A signalling NaN with the node's tag and a plausible address in its
    // payload, and the quiet NaN arithmetic makes.
    for (const std::uint64_t bits :
         {std::uint64_t(0x7FF4000012345678), std::uint64_t(0x7FF4000000000000),
          std::bit_cast<std::uint64_t>(std::sqrt(-1.0))}) {
        const TimeFunction f(std::bit_cast<double>(bits));
        CHECK(f.is_constant());
        CHECK(f.node() == nullptr);
        CHECK(std::isnan(f.constant()));
        CHECK(std::isnan(f(0.5)));
    }

    const TimeFunction moving = TimeFunction::clock() * 2.0 + 1.0;
    REQUIRE(moving.depends_on_time());
    std::vector<TimeFunction> copies(100, moving);
    for (const auto& c : copies) CHECK(c.node() == moving.node());
    TimeFunction assigned = 3.0;
    assigned = copies.back();
    copies.clear();  // the node outlives the copies that went
    CHECK(assigned(0.25) == 1.5);
    assigned = assigned;  // NOLINT: self-assignment keeps the node
    CHECK(assigned(0.25) == 1.5);
    TimeFunction moved = std::move(assigned);
    CHECK(moved(1.0) == 3.0);
    CHECK(assigned.is_constant());  // NOLINT: a moved-from function is the constant 0
    CHECK(assigned.constant() == 0.0);
    // Every use of clock is one node.
    CHECK(TimeFunction::clock().node() == TimeFunction::clock().node());
}
