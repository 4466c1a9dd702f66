// Time tapes against the time functions they were compiled from, on random
// expression DAGs over every TimeOp and every spline kind: the point
// evaluator equals TimeFunction(t) bit for bit, the interval evaluator holds
// the point values of every t inside, and the dual evaluator's derivative
// matches finite differences where the function is smooth.
#include "runtime/time/time_tape.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <vector>

#include <catch2/catch.hpp>

#include "runtime/motion/spline.hpp"
#include "runtime/time/compiled_function.hpp"
#include "runtime/time/dual.hpp"
#include "runtime/time/interval.hpp"
#include "runtime/time/point_function.hpp"
#include "runtime/time/time_function.hpp"
#include "runtime/time/time_ops.hpp"
#include "runtime/time/time_ops_generic.hpp"
#include "same_bits.hpp"

using hexant::runtime::arity;
using hexant::runtime::CompiledScalar;
using hexant::runtime::CompiledVector3;
using hexant::runtime::Dual;
using hexant::runtime::Interval;
using hexant::runtime::Spline;
using hexant::runtime::SplineKind;
using hexant::runtime::TimeFunction;
using hexant::runtime::TimeOp;
using hexant::runtime::TimeTape;
using hexant::test::same_bits;

namespace {

// Random DAGs: each new node applies a random operation to earlier nodes,
// recent ones more often (depth) but any of them (sharing). Arguments of
// functions with a restricted domain are mostly mapped into it first, so
// that most samples have no NaN anywhere.
class DagSource {
  public:
    explicit DagSource(std::uint64_t seed) : rng_(seed) {}

    std::vector<TimeFunction> build(int nodes) {
        const TimeFunction t = TimeFunction::clock();
        pool_ = {t, t * 0.7 + 0.2, TimeFunction::clock() * -1.3 + 0.5, sin(t * 3.0)};
        while (static_cast<int>(pool_.size()) < nodes) pool_.push_back(random_node());
        return {pool_.end() - 3, pool_.end()};
    }

  private:
    double unit() { return std::uniform_real_distribution<double>(0.0, 1.0)(rng_); }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
    bool chance(double p) { return unit() < p; }

    static TimeFunction sin(const TimeFunction& x) { return TimeFunction::apply(TimeOp::Sin, x); }

    TimeFunction pick() {
        // Mostly recent nodes, sometimes constants.
        if (chance(0.1)) return TimeFunction(std::round(unit() * 8.0 - 4.0) * 0.5);
        const int n = static_cast<int>(pool_.size());
        const int back = chance(0.6) ? integer(1, std::min(n, 4)) : integer(1, n);
        return pool_[n - back];
    }

    // Keeps values moderate: x / (1 + |x|) in (-1, 1).
    static TimeFunction squash(const TimeFunction& x) {
        return x / (TimeFunction::apply(TimeOp::Abs, x) + 1.0);
    }
    static TimeFunction positive(const TimeFunction& x) {
        return TimeFunction::apply(TimeOp::Abs, x) + 0.05;
    }

    TimeFunction random_node() {
        const int choice =
            integer(static_cast<int>(TimeOp::Negate), static_cast<int>(TimeOp::SplineComponent));
        const TimeOp op = static_cast<TimeOp>(choice);
        const bool safe = chance(0.85);
        const TimeFunction a = pick(), b = pick(), c = pick();
        switch (op) {
            case TimeOp::Asin:
            case TimeOp::Acos:
                return TimeFunction::apply(op, safe ? squash(a) : a);
            case TimeOp::Sqrt:
            case TimeOp::Ln:
            case TimeOp::Log10:
                return TimeFunction::apply(op, safe ? positive(a) : a);
            case TimeOp::Exp:
            case TimeOp::Tan:
            case TimeOp::Sin:
            case TimeOp::Cos:
                return TimeFunction::apply(op, safe ? a * 2.0 : a);
            case TimeOp::Divide:
            case TimeOp::Mod:
            case TimeOp::IntDiv:
                return TimeFunction::apply(op, a * 3.0, safe ? positive(b) : b);
            case TimeOp::Pow:
                if (chance(0.4)) return TimeFunction::apply(op, a, double(integer(-3, 4)));
                return TimeFunction::apply(op, safe ? positive(a) : a, squash(b) * 3.0);
            case TimeOp::Int:
            case TimeOp::Floor:
            case TimeOp::Ceil:
                return TimeFunction::apply(op, a * 3.0);
            case TimeOp::SplineComponent:
                return spline_of(a);
            default:
                break;
        }
        switch (arity(op)) {
            case 1:
                return TimeFunction::apply(op, a);
            case 2:
                return TimeFunction::apply(op, a, b);
            default:
                return TimeFunction::apply(op, a, b, c);
        }
    }

    TimeFunction spline_of(const TimeFunction& p) {
        const SplineKind kind = static_cast<SplineKind>(integer(0, 3));
        std::vector<Spline::Key> keys;
        const int n = integer(1, 6);
        double t = -1.5;
        for (int i = 0; i < n; ++i) {
            keys.push_back({t, {unit() * 4 - 2, unit() * 4 - 2, unit() * 4 - 2, 0, 0}});
            t += 0.2 + unit();
        }
        auto spline = std::make_shared<const Spline>(kind, keys, 3);
        return TimeFunction::spline_component(spline, integer(0, 2), p);
    }

    std::mt19937_64 rng_;
    std::vector<TimeFunction> pool_;
};

}  // namespace

TEST_CASE("a tape at a point equals the time function exactly", "[runtime][time]") {
    DagSource source(31);
    std::mt19937_64 rng(32);
    std::uniform_real_distribution<double> time(-2.0, 3.0);
    long compared = 0;
    for (int dag = 0; dag < 400; ++dag) {
        const std::vector<TimeFunction> functions = source.build(4 + dag % 30);
        const TimeTape tape = TimeTape::compile(functions);
        REQUIRE(tape.output_count() == functions.size());
        for (int s = 0; s < 50; ++s) {
            const double t = time(rng);
            double out[3];
            Dual dual[3];
            tape.evaluate(t, out);
            tape.evaluate(Dual::variable(t), dual);
            for (std::size_t i = 0; i < functions.size(); ++i) {
                const double want = functions[i](t);
                if (!same_bits(out[i], want) || !same_bits(dual[i].v, want)) {
                    INFO(functions[i].to_string() << " at " << t);
                    CHECK(out[i] == want);
                    CHECK(dual[i].v == want);
                }
                ++compared;
            }
        }
    }
    CHECK(compared == 400 * 50 * 3);
}

TEST_CASE("a tape shares nodes, clock and constants", "[runtime][time]") {
    const TimeFunction t = TimeFunction::clock();
    const TimeFunction shared = TimeFunction::apply(TimeOp::Sin, t * 2.0);
    const TimeFunction f = shared * shared + shared;
    const TimeFunction g = TimeFunction::clock() * 2.0;  // another clock node, same constant
    const TimeTape tape = TimeTape::compile({f, g, TimeFunction(5.0)});
    // clock, 2, t*2, sin, *, +, clock*2 (a node of its own), 5.
    CHECK(tape.size() == 8);
    CHECK_FALSE(tape.is_constant(0));
    CHECK(tape.is_constant(2));
    CHECK(tape.constant(2) == 5.0);
    double out[3];
    tape.evaluate(0.3, out);
    CHECK(out[0] == f(0.3));
    CHECK(out[1] == 0.6);
    CHECK(out[2] == 5.0);
}

TEST_CASE("a tape over an interval holds every point value inside", "[runtime][time]") {
    DagSource source(33);
    std::mt19937_64 rng(34);
    std::uniform_real_distribution<double> time(-2.0, 3.0), unit(0.0, 1.0);
    long checked = 0, skipped = 0;
    for (int dag = 0; dag < 400; ++dag) {
        const std::vector<TimeFunction> functions = source.build(4 + dag % 30);
        const TimeTape tape = TimeTape::compile(functions);
        std::vector<double> scratch(tape.size());
        for (int s = 0; s < 12; ++s) {
            const double a = time(rng);
            const double width = std::pow(10.0, -6.0 * unit(rng)) * (s % 3 == 0 ? 0.0 : 1.0);
            const Interval span{a, a + width};
            Interval range[3];
            tape.evaluate(span, range);
            for (int k = 0; k < 20; ++k) {
                const double t = k == 0 ? span.lo : k == 1 ? span.hi : a + width * unit(rng);
                double out[3];
                tape.evaluate(t, out, scratch.data());
                // Only where every slot has a value: a NaN (outside a
                // domain) has nothing to be held, and can turn a comparison.
                bool defined = true;
                for (double v : scratch) defined = defined && !std::isnan(v);
                if (!defined) {
                    ++skipped;
                    continue;
                }
                for (std::size_t i = 0; i < functions.size(); ++i) {
                    if (!range[i].contains(out[i])) {
                        INFO(functions[i].to_string() << " over " << span << " -> " << range[i]
                                                      << " at " << t << " = " << out[i]);
                        CHECK(range[i].contains(out[i]));
                    }
                    ++checked;
                }
            }
        }
    }
    INFO("checked " << checked << " skipped " << skipped);
    CHECK(checked > 200000);
    CHECK(skipped < checked / 3);
}

TEST_CASE("a tape's derivative matches finite differences where smooth", "[runtime][time]") {
    DagSource source(35);
    std::mt19937_64 rng(36);
    std::uniform_real_distribution<double> time(-2.0, 3.0);
    long checked = 0, skipped = 0;
    for (int dag = 0; dag < 400; ++dag) {
        const std::vector<TimeFunction> functions = source.build(4 + dag % 30);
        const TimeTape tape = TimeTape::compile(functions);
        for (int s = 0; s < 20; ++s) {
            const double t = time(rng);
            Dual d[3];
            tape.evaluate(Dual::variable(t), d);
            for (std::size_t i = 0; i < functions.size(); ++i) {
                const TimeFunction& f = functions[i];
                // Central differences at two steps; where they disagree, the
                // function jumps or bends sharply near t: not smooth there.
                const double h = 1e-5;
                const double v = f(t);
                const double fd1 = (f(t + h) - f(t - h)) / (2 * h);
                const double fd2 = (f(t + h / 2) - f(t - h / 2)) / h;
                // And where t itself is no isolated spike (a jump of rounding
                // size, as fmod(3 x, x) has).
                const double noise = 1e-9 * std::fabs(v) / h;
                const double bend = f(t + h) + f(t - h) - 2 * v;
                const bool smooth = std::isfinite(v) && std::isfinite(fd1) && std::isfinite(fd2) &&
                                    std::fabs(fd1 - fd2) <= 1e-5 * (1 + std::fabs(fd2)) + noise &&
                                    std::fabs(bend) <= 1e-6 * (1 + std::fabs(v));
                if (!smooth || !std::isfinite(d[i].d)) {
                    ++skipped;
                    continue;
                }
                // Richardson: (4 fd2 - fd1) / 3 cancels the h^2 term.
                const double fd = (4 * fd2 - fd1) / 3;
                INFO(f.to_string() << " at " << t << ": " << d[i] << " vs " << fd);
                CHECK(d[i].d == Approx(fd).epsilon(1e-4).margin(1e-6 + 10 * noise));
                ++checked;
            }
        }
    }
    INFO("checked " << checked << " skipped " << skipped);
    CHECK(checked > 15000);
}

TEST_CASE("every operation over intervals and duals, one at a time", "[runtime][time]") {
    // Each operation on arguments a + b t etc., over short and long spans.
    const TimeFunction t = TimeFunction::clock();
    const TimeFunction x = t * 0.9 - 0.3, y = t * -0.4 + 0.6, z = t * 1.7 + 0.1;
    std::mt19937_64 rng(37);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int k = static_cast<int>(TimeOp::Negate); k <= static_cast<int>(TimeOp::Conditional);
         ++k) {
        const TimeOp op = static_cast<TimeOp>(k);
        INFO(hexant::runtime::name(op));
        const TimeFunction f = arity(op) == 1   ? TimeFunction::apply(op, x)
                               : arity(op) == 2 ? TimeFunction::apply(op, x, y)
                                                : TimeFunction::apply(op, x, y, z);
        const CompiledScalar compiled(f);
        REQUIRE_FALSE(compiled.is_constant());
        for (int s = 0; s < 300; ++s) {
            const double a = 3.0 * unit(rng) - 1.0, w = s % 2 ? 1e-3 * unit(rng) : unit(rng);
            const Interval span{a, a + w};
            const Interval range = compiled.over(span);
            CHECK_FALSE(std::isnan(range.lo));
            CHECK_FALSE(std::isnan(range.hi));
            for (int j = 0; j <= 10; ++j) {
                const double time = std::min(a + w * j / 10.0, span.hi);
                const double v = f(time);
                if (!std::isnan(v) && !range.contains(v)) {
                    INFO("over [" << a << ", " << a + w << "] -> " << range << " at " << time);
                    CHECK(range.contains(v));
                }
                CHECK(same_bits(compiled.with_derivative(time).v, v));
                CHECK(same_bits(compiled.at(time), v));
            }
        }
    }
}

TEST_CASE("decided and undecided truth over intervals", "[runtime][time]") {
    using hexant::runtime::apply_op;
    const Interval low{0.0, 1.0}, high{2.0, 3.0}, across{0.5, 2.5};
    CHECK(apply_op(TimeOp::Less, low, high).lo == 1.0);
    CHECK(apply_op(TimeOp::Less, high, low).hi == 0.0);
    CHECK(apply_op(TimeOp::Less, low, across).width() == 1.0);
    CHECK(apply_op(TimeOp::Equal, Interval(1.0), Interval(1.0 + 1e-11)).lo == 1.0);
    CHECK(apply_op(TimeOp::Equal, low, high).hi == 0.0);
    CHECK(apply_op(TimeOp::And, high, Interval(0.0)).hi == 0.0);
    CHECK(apply_op(TimeOp::Or, high, Interval(-1.0, 1.0)).lo == 1.0);
    CHECK(apply_op(TimeOp::Not, Interval(-1.0, 1.0)).width() == 1.0);
    // select: decided picks a branch, undecided takes the hull.
    const Interval picked = apply_op(TimeOp::Select, Interval(-2.0, -1.0), low, high);
    CHECK(picked.lo == 0.0);
    CHECK(picked.hi == 1.0);
    const Interval both = apply_op(TimeOp::Select, Interval(-1.0, 1.0), low, high);
    CHECK(both.lo == 0.0);
    CHECK(both.hi == 3.0);
    const Interval cond = apply_op(TimeOp::Conditional, Interval(0.0), low, high);
    CHECK(cond.lo == 2.0);
    // mod within one period is tight: fmod([5.2, 5.8], 2) = [1.2, 1.8].
    const Interval m = apply_op(TimeOp::Mod, Interval(5.2, 5.8), Interval(2.0));
    CHECK(m.lo == Approx(1.2));
    CHECK(m.hi == Approx(1.8));
}

TEST_CASE("compiled functions skip the tape when constant", "[runtime][time]") {
    const CompiledScalar c(TimeFunction(2.5));
    CHECK(c.is_constant());
    CHECK(c.at(7.0) == 2.5);
    CHECK(c.over(Interval(0, 1)).lo == 2.5);
    CHECK(c.with_derivative(1.0).d == 0.0);

    const TimeFunction t = TimeFunction::clock();
    hexant::runtime::Vector3Function moving{{t * 2.0, TimeFunction(1.0), t * t}};
    const CompiledVector3 v(moving);
    CHECK_FALSE(v.is_constant());
    CHECK(v.at(3.0) == glm::dvec3(6.0, 1.0, 9.0));
    const auto r = v.over(Interval(1.0, 2.0));
    CHECK(r[0].contains(2.0));
    CHECK(r[0].contains(4.0));
    CHECK(r[1].lo == 1.0);
    CHECK(r[2].lo <= 1.0);
    CHECK(r[2].hi >= 4.0);
    CHECK(r[2].hi < 4.0001);
    const auto d = v.with_derivative(3.0);
    CHECK(d[0].d == 2.0);
    CHECK(d[1].d == 0.0);
    CHECK(d[2].d == 6.0);

    const CompiledVector3 still(hexant::runtime::Vector3Function{{1.0, 2.0, 3.0}});
    CHECK(still.is_constant());
    CHECK(still.at(0.0) == glm::dvec3(1, 2, 3));
}

namespace {

// f(p, t) = p.x * p.y + t * p.z, with its interval bound and gradient.
struct TestPointFunction final : hexant::runtime::PointFunction {
    bool moves = true;
    std::string name() const override { return "test function"; }
    int components() const override { return 1; }
    bool depends_on_time() const override { return moves; }
    double at(int, const glm::dvec3& p, double t) const override {
        return p.x * p.y + (moves ? t : 0.0) * p.z;
    }
    bool bounded() const override { return true; }
    Interval over(int, const std::array<Interval, 3>& p, const Interval& t) const override {
        return p[0] * p[1] + (moves ? t : Interval(0.0)) * p[2];
    }
    std::array<double, 4> gradient(int, const glm::dvec3& p, double t) const override {
        return {p.y, p.x, moves ? t : 0.0, moves ? p.z : 0.0};
    }
};

// A function with no bound (a pigment's kind).
struct UnboundedPointFunction final : hexant::runtime::PointFunction {
    std::string name() const override { return "unbounded"; }
    int components() const override { return 1; }
    bool depends_on_time() const override { return false; }
    double at(int, const glm::dvec3& p, double) const override { return p.x; }
};

}  // namespace

TEST_CASE("a point call hands its point and time to its function", "[runtime][time]") {
    using hexant::runtime::TimeOp;
    using hexant::runtime::TimeTape;
    const auto f = std::make_shared<const TestPointFunction>();
    const TimeFunction t = TimeFunction::clock();
    // f(t, 2t, 1) = 2 t^2 + t.
    const TimeFunction g = TimeFunction::point_call(f, 0, t, t * 2.0, 1.0);
    REQUIRE_FALSE(g.is_constant());
    CHECK(g(0.5) == 1.0);
    const TimeTape tape = TimeTape::compile({g});
    CHECK(tape.reads_time());
    CHECK(tape.point_functions_bounded());
    double out = 0.0;
    tape.evaluate<double>(0.75, &out);
    CHECK(out == g(0.75));
    Dual d(0.0);
    tape.evaluate<Dual>(Dual(0.75, 1.0), &d);
    CHECK(d.v == g(0.75));
    CHECK(d.d == Approx(4 * 0.75 + 1));
    Interval range(0.0);
    tape.evaluate<Interval>(Interval(0.25, 0.5), &range);
    for (double s = 0.25; s <= 0.5; s += 1.0 / 64) CHECK(range.contains(g(s)));

    // A function of (x, y, z): a call substitutes its arguments.
    const TimeFunction body = TimeFunction::point_call(
        f, 0, TimeFunction::argument(0), TimeFunction::argument(1), TimeFunction::argument(2));
    const TimeFunction call = hexant::runtime::substitute_arguments(body, {2.0, 3.0, t});
    CHECK(call(0.5) == 6.25);
    // A still function at a constant point folds to a number.
    auto still = std::make_shared<TestPointFunction>();
    still->moves = false;
    const TimeFunction folded = TimeFunction::point_call(still, 0, 2.0, 3.0, 4.0);
    REQUIRE(folded.is_constant());
    CHECK(folded.constant() == 6.0);

    // Without a bound the interval is everything and the tape says so.
    const auto loose = std::make_shared<const UnboundedPointFunction>();
    const TimeTape unbounded = TimeTape::compile(
        {TimeFunction::point_call(loose, 0, TimeFunction::argument(0), 1.0, 1.0)});
    CHECK(unbounded.unbounded_point_function() == loose.get());
    CHECK_FALSE(unbounded.reads_time());
    Interval everything(0.0);
    const Interval x(0.0, 1.0);
    std::vector<Interval> scratch(unbounded.size());
    unbounded.evaluate_with<Interval>(Interval(0.0, 1.0), &x, &everything, scratch.data());
    CHECK(everything.lo == -std::numeric_limits<double>::infinity());
    CHECK(everything.hi == std::numeric_limits<double>::infinity());
}
