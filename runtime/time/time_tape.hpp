// Time functions compiled to a tape: the DAG of TimeFunction nodes flattened
// into instructions in dependency order, each writing one slot. Shared
// sub-functions (the same node reached twice) are computed once, as are
// `clock` and equal constants.
//
// One tape, three evaluators, chosen by the number type:
//   double   - the point value, equal bit for bit to TimeFunction(t);
//   Interval - a range that holds the point value for every t in the interval;
//   Dual     - the point value and its derivative in t;
//   IntervalJet - over an interval of times, the range, the first two
//              derivatives' ranges and the double evaluation's rounding
//              radius (interval_jet.hpp), for sweeps that follow the motion.
// Both branches of select and ?: are computed (no jumps); at a point that
// changes nothing, since operations have no side effects.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "runtime/motion/spline.hpp"
#include "runtime/motion/spline_bounds.hpp"
#include "runtime/time/dual.hpp"
#include "runtime/time/interval.hpp"
#include "runtime/time/interval_jet.hpp"
#include "runtime/time/point_function.hpp"
#include "runtime/time/point_range.hpp"
#include "runtime/time/time_function.hpp"

namespace hexant::runtime {

class TimeTape {
  public:
    struct Instruction {
        TimeOp op = TimeOp::Constant;
        std::uint32_t a = 0, b = 0, c = 0;  // argument slots (earlier instructions)
        double constant = 0.0;              // for Constant
        std::uint32_t spline = 0;           // for SplineComponent: index into the splines,
                                            // for PointCall into the point functions
        int component = 0;                  // for SplineComponent, PointCall
    };

    // One output per function, in order.
    static TimeTape compile(const std::vector<TimeFunction>& outputs);

    // Slots (= instructions); evaluate's scratch needs this many numbers.
    std::size_t size() const { return code_.size(); }
    std::size_t output_count() const { return outputs_.size(); }
    bool is_constant(std::size_t output) const {
        return code_[outputs_[output]].op == TimeOp::Constant;
    }
    // The constant value of an output; only valid when is_constant(output).
    double constant(std::size_t output) const { return code_[outputs_[output]].constant; }
    const std::vector<Instruction>& instructions() const { return code_; }
    // Whether an output may change with t: the tape reads clock, or calls a
    // point function that moves.
    bool reads_time() const;
    // Whether every point function it calls bounds itself
    // (PointFunction::bounded): then its Interval evaluation is a bound.
    bool point_functions_bounded() const;
    // The first point function it calls that cannot bound itself, or null.
    const PointFunction* unbounded_point_function() const;

    // Evaluate all outputs at t (a point, an interval of times, or a point
    // with derivative 1). scratch must hold size() numbers.
    template <class Number>
    void evaluate(Number t, Number* outputs, Number* scratch) const;

    // A user function's tape (runtime/time/user_function.hpp): arguments[k]
    // is its argument k, for k < argument_count(). evaluate() refuses such
    // a tape.
    template <class Number>
    void evaluate_with(Number t, const Number* arguments, Number* outputs, Number* scratch) const;
    int argument_count() const { return argument_count_; }

    // As above, with scratch on the stack for small tapes.
    template <class Number>
    void evaluate(Number t, Number* outputs) const;

  private:
    double spline_value(const Instruction& in, double p) const;
    Interval spline_value(const Instruction& in, const Interval& p) const;
    Dual spline_value(const Instruction& in, const Dual& p) const;
    IntervalJet spline_value(const Instruction& in, const IntervalJet& p) const;
    PointRange spline_value(const Instruction& in, const PointRange& p) const;

    // PointCall at (x, y, z) (and the time t, for the derivative in t).
    double point_value(const Instruction& in, double t, double x, double y, double z) const;
    Interval point_value(const Instruction& in, const Interval& t, const Interval& x,
                         const Interval& y, const Interval& z) const;
    Dual point_value(const Instruction& in, const Dual& t, const Dual& x, const Dual& y,
                     const Dual& z) const;
    IntervalJet point_value(const Instruction& in, const IntervalJet& t, const IntervalJet& x,
                            const IntervalJet& y, const IntervalJet& z) const;
    PointRange point_value(const Instruction& in, const PointRange& t, const PointRange& x,
                           const PointRange& y, const PointRange& z) const;

    std::vector<Instruction> code_;
    std::vector<std::uint32_t> outputs_;
    int argument_count_ = 0;
    std::vector<std::shared_ptr<const Spline>> splines_;
    std::vector<SplineBounds> spline_bounds_;  // beside splines_
    std::vector<std::shared_ptr<const PointFunction>> point_functions_;
};

// Defined in time_tape.cpp for these three number types.
extern template void TimeTape::evaluate<double>(double, double*, double*) const;
extern template void TimeTape::evaluate<PointRange>(PointRange, PointRange*, PointRange*) const;
extern template void TimeTape::evaluate<Interval>(Interval, Interval*, Interval*) const;
extern template void TimeTape::evaluate<Dual>(Dual, Dual*, Dual*) const;
extern template void TimeTape::evaluate<IntervalJet>(IntervalJet, IntervalJet*, IntervalJet*) const;
extern template void TimeTape::evaluate_with<double>(double, const double*, double*, double*) const;
extern template void TimeTape::evaluate_with<Interval>(Interval, const Interval*, Interval*,
                                                       Interval*) const;
extern template void TimeTape::evaluate_with<Dual>(Dual, const Dual*, Dual*, Dual*) const;
extern template void TimeTape::evaluate<double>(double, double*) const;
extern template void TimeTape::evaluate<Interval>(Interval, Interval*) const;
extern template void TimeTape::evaluate<Dual>(Dual, Dual*) const;
extern template void TimeTape::evaluate<IntervalJet>(IntervalJet, IntervalJet*) const;

}  // namespace hexant::runtime
