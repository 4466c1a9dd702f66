// A time function that is a constant or a line in clock, a + b clock, kept
// as two numbers instead of a tape. Most motion in real animations is this
// (`rotate y * 360 * clock`, `translate <clock, 0, 0>`, `rotate y * (Start +
// Turns * 360 * clock)`), and a tape for it costs about 400 bytes per object
// (its instructions, outputs and shared block) and a loop per evaluation.
//
// The line keeps the operations and their order as the language built them
// (POV-Ray's left-to-right arithmetic, e.g. `(k * clock) + a`, `clock / k -
// a`), and evaluates them with the same apply_op as the tape (time_ops.hpp,
// time_ops_generic.hpp, interval_jet.hpp), so that for every number type
// (double, Interval, Dual, IntervalJet) its value is the tape's, bit for bit.
#pragma once

#include <cstdint>
#include <optional>

#include "runtime/time/interval_jet.hpp"
#include "runtime/time/time_function.hpp"
#include "runtime/time/time_ops.hpp"
#include "runtime/time/time_ops_generic.hpp"

namespace hexant::runtime {

class ClockLine {
  public:
    ClockLine() = default;  // the constant 0
    static ClockLine constant(double value) {
        ClockLine line;
        line.offset_ = value;
        return line;
    }

    // f as a line, if it is a constant or one of: clock; clock * k, k *
    // clock, clock / k; any of those plus or minus a constant a, on either
    // side (k and a constants). Nothing for anything else.
    static std::optional<ClockLine> of(const TimeFunction& f) {
        if (f.is_constant()) return constant(f.constant());
        ClockLine line;
        line.outer_ = Op::None;
        const TimeFunction::Node* n = f.node();
        if (n->op == TimeOp::Add || n->op == TimeOp::Subtract) {
            const TimeFunction& a = n->args[0];
            const TimeFunction& b = n->args[1];
            if (a.is_constant() == b.is_constant()) return std::nullopt;
            line.outer_ = n->op == TimeOp::Add ? Op::Add : Op::Subtract;
            line.offset_first_ = a.is_constant();
            line.offset_ = line.offset_first_ ? a.constant() : b.constant();
            n = (line.offset_first_ ? b : a).node();
        }
        if (n->op == TimeOp::Multiply || n->op == TimeOp::Divide) {
            const TimeFunction& a = n->args[0];
            const TimeFunction& b = n->args[1];
            if (a.is_constant() == b.is_constant()) return std::nullopt;
            if (n->op == TimeOp::Divide && a.is_constant()) return std::nullopt;  // k / clock
            line.inner_ = n->op == TimeOp::Multiply ? Op::Multiply : Op::Divide;
            line.scale_first_ = a.is_constant();
            line.scale_ = line.scale_first_ ? a.constant() : b.constant();
            n = (line.scale_first_ ? b : a).node();
        }
        if (n->op != TimeOp::Clock) return std::nullopt;
        return line;
    }

    bool is_constant() const { return outer_ == Op::Constant; }
    // The value when is_constant().
    double constant_value() const { return offset_; }

    // The value at t: a time, an interval of times, or a time with its
    // derivative, as the tape computes it.
    template <class N>
    N at(const N& t) const {
        if (outer_ == Op::Constant) return N(offset_);
        N v = t;
        if (inner_ != Op::None) {
            const TimeOp op = inner_ == Op::Multiply ? TimeOp::Multiply : TimeOp::Divide;
            v = scale_first_ ? apply_op(op, N(scale_), v) : apply_op(op, v, N(scale_));
        }
        if (outer_ != Op::None) {
            const TimeOp op = outer_ == Op::Add ? TimeOp::Add : TimeOp::Subtract;
            v = offset_first_ ? apply_op(op, N(offset_), v) : apply_op(op, v, N(offset_));
        }
        return v;
    }

  private:
    enum class Op : std::uint8_t { Constant, None, Add, Subtract, Multiply, Divide };
    double offset_ = 0.0;  // a (the constant's value for a constant)
    double scale_ = 1.0;   // k
    Op outer_ = Op::Constant;
    Op inner_ = Op::None;
    bool offset_first_ = false;
    bool scale_first_ = false;
};

}  // namespace hexant::runtime
