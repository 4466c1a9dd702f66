#include "runtime/time/time_tape.hpp"

#include <algorithm>
#include <bit>
#include <optional>
#include <stdexcept>
#include <unordered_map>

#include "runtime/time/time_ops.hpp"
#include "runtime/time/time_ops_generic.hpp"

namespace hexant::runtime {

namespace {

// Builds the instruction list; every slot is emitted once.
class TapeBuilder {
  public:
    std::vector<TimeTape::Instruction> code;
    std::vector<std::shared_ptr<const Spline>> splines;
    std::vector<std::shared_ptr<const PointFunction>> point_functions;
    int arguments = 0;  // 1 + the largest argument index read

    std::uint32_t constant(double value) {
        const auto key = std::bit_cast<std::uint64_t>(value);  // -0 and 0 stay apart
        const auto found = constants_.find(key);
        if (found != constants_.end()) return found->second;
        TimeTape::Instruction in;
        in.op = TimeOp::Constant;
        in.constant = value;
        return constants_[key] = emit(in);
    }

    std::uint32_t slot(const TimeFunction& f) {
        if (f.is_constant()) return constant(f.constant());
        // Depth-first, children before parents, without recursion: time
        // functions built in loops can be very deep.
        std::vector<const TimeFunction::Node*> stack{f.node()};
        while (!stack.empty()) {
            const TimeFunction::Node* node = stack.back();
            if (nodes_.count(node)) {
                stack.pop_back();
                continue;
            }
            const int n = arity(node->op);
            bool ready = true;
            for (int i = 0; i < n; ++i) {
                const TimeFunction& arg = node->args[i];
                if (!arg.is_constant() && !nodes_.count(arg.node())) {
                    stack.push_back(arg.node());
                    ready = false;
                }
            }
            if (!ready) continue;
            nodes_[node] = emit_node(*node);
            stack.pop_back();
        }
        return nodes_.at(f.node());
    }

  private:
    std::uint32_t emit(const TimeTape::Instruction& in) {
        code.push_back(in);
        return static_cast<std::uint32_t>(code.size() - 1);
    }

    std::uint32_t argument(const TimeFunction& arg) {
        return arg.is_constant() ? constant(arg.constant()) : nodes_.at(arg.node());
    }

    std::uint32_t emit_node(const TimeFunction::Node& node) {
        TimeTape::Instruction in;
        in.op = node.op;
        switch (node.op) {
            case TimeOp::Clock:
                if (!clock_) clock_ = emit(in);
                return *clock_;
            case TimeOp::Argument:
                in.component = node.component;
                arguments = std::max(arguments, node.component + 1);
                return emit(in);
            case TimeOp::Constant:
                throw std::logic_error("a constant time function node");
            case TimeOp::SplineComponent: {
                in.a = argument(node.args[0]);
                const auto found = spline_index_.find(node.spline.get());
                if (found != spline_index_.end()) {
                    in.spline = found->second;
                } else {
                    in.spline = static_cast<std::uint32_t>(splines.size());
                    spline_index_[node.spline.get()] = in.spline;
                    splines.push_back(node.spline);
                }
                in.component = node.component;
                return emit(in);
            }
            case TimeOp::PointCall: {
                in.a = argument(node.args[0]);
                in.b = argument(node.args[1]);
                in.c = argument(node.args[2]);
                const auto found = point_index_.find(node.point_function.get());
                if (found != point_index_.end()) {
                    in.spline = found->second;
                } else {
                    in.spline = static_cast<std::uint32_t>(point_functions.size());
                    point_index_[node.point_function.get()] = in.spline;
                    point_functions.push_back(node.point_function);
                }
                in.component = node.component;
                return emit(in);
            }
            default:
                break;
        }
        const int n = arity(node.op);
        if (n >= 1) in.a = argument(node.args[0]);
        if (n >= 2) in.b = argument(node.args[1]);
        if (n >= 3) in.c = argument(node.args[2]);
        return emit(in);
    }

    std::unordered_map<std::uint64_t, std::uint32_t> constants_;
    std::unordered_map<const TimeFunction::Node*, std::uint32_t> nodes_;
    std::unordered_map<const Spline*, std::uint32_t> spline_index_;
    std::unordered_map<const PointFunction*, std::uint32_t> point_index_;
    std::optional<std::uint32_t> clock_;
};

}  // namespace

TimeTape TimeTape::compile(const std::vector<TimeFunction>& outputs) {
    TapeBuilder builder;
    TimeTape tape;
    for (const TimeFunction& f : outputs) tape.outputs_.push_back(builder.slot(f));
    tape.code_ = std::move(builder.code);
    tape.splines_ = std::move(builder.splines);
    tape.point_functions_ = std::move(builder.point_functions);
    tape.argument_count_ = builder.arguments;
    for (const auto& spline : tape.splines_) tape.spline_bounds_.emplace_back(*spline);
    return tape;
}

double TimeTape::spline_value(const Instruction& in, double p) const {
    return splines_[in.spline]->evaluate(p)[in.component];
}

Interval TimeTape::spline_value(const Instruction& in, const Interval& p) const {
    return spline_bounds_[in.spline].range(in.component, p);
}

Dual TimeTape::spline_value(const Instruction& in, const Dual& p) const {
    const double derivative = spline_bounds_[in.spline].derivative(in.component, p.v);
    return {spline_value(in, p.v), p.d == 0.0 ? 0.0 : derivative * p.d};
}

// A spline's pieces meet with kinks (and held values jump): its range only,
// with no linear form.
IntervalJet TimeTape::spline_value(const Instruction& in, const IntervalJet& p) const {
    const Interval range = spline_value(in, p.v);
    if (p.d.lo == 0.0 && p.d.hi == 0.0 && p.r == 0.0 && p.v.is_point())
        return {range, Interval(0.0), Interval(0.0),
                range.width()};  // both values lie in the range
    return IntervalJet::unknown(range);
}

bool TimeTape::reads_time() const {
    for (const Instruction& in : code_)
        if (in.op == TimeOp::Clock) return true;
    for (const auto& f : point_functions_)
        if (f->depends_on_time()) return true;
    return false;
}

bool TimeTape::point_functions_bounded() const {
    return unbounded_point_function() == nullptr;
}

const PointFunction* TimeTape::unbounded_point_function() const {
    for (const auto& f : point_functions_)
        if (!f->bounded()) return f.get();
    return nullptr;
}

double TimeTape::point_value(const Instruction& in, double t, double x, double y, double z) const {
    return point_functions_[in.spline]->at(in.component, {x, y, z}, t);
}

Interval TimeTape::point_value(const Instruction& in, const Interval& t, const Interval& x,
                               const Interval& y, const Interval& z) const {
    return point_functions_[in.spline]->over(in.component, {x, y, z}, t);
}

// The chain rule through the function's gradient (NaN where it has none).
Dual TimeTape::point_value(const Instruction& in, const Dual& t, const Dual& x, const Dual& y,
                           const Dual& z) const {
    const PointFunction& f = *point_functions_[in.spline];
    const glm::dvec3 p{x.v, y.v, z.v};
    const double value = f.at(in.component, p, t.v);
    if (x.d == 0.0 && y.d == 0.0 && z.d == 0.0 && (t.d == 0.0 || !f.depends_on_time()))
        return {value, 0.0};
    const std::array<double, 4> g = f.gradient(in.component, p, t.v);
    double d = 0.0;
    if (x.d != 0.0) d += g[0] * x.d;
    if (y.d != 0.0) d += g[1] * y.d;
    if (z.d != 0.0) d += g[2] * z.d;
    if (t.d != 0.0 && f.depends_on_time()) d += g[3] * t.d;
    return {value, d};
}

// Its range only, with no linear form (as a spline's).
IntervalJet TimeTape::point_value(const Instruction& in, const IntervalJet& t, const IntervalJet& x,
                                  const IntervalJet& y, const IntervalJet& z) const {
    return IntervalJet::unknown(point_value(in, t.v, x.v, y.v, z.v));
}

PointRange TimeTape::point_value(const Instruction& in, const PointRange& t, const PointRange& x,
                                 const PointRange& y, const PointRange& z) const {
    return PointRange(point_value(in, t.v, x.v, y.v, z.v));
}

template <class Number>
void TimeTape::evaluate(Number t, Number* outputs, Number* scratch) const {
    if (argument_count_ > 0)
        throw std::logic_error("a tape of a user function evaluated without its arguments");
    evaluate_with<Number>(t, nullptr, outputs, scratch);
}

template <class Number>
void TimeTape::evaluate_with(Number t, const Number* arguments, Number* outputs,
                             Number* scratch) const {
    const std::size_t n = code_.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Instruction& in = code_[i];
        switch (in.op) {
            case TimeOp::Constant:
                scratch[i] = Number(in.constant);
                break;
            case TimeOp::Clock:
                scratch[i] = t;
                break;
            case TimeOp::Argument:
                scratch[i] = arguments[in.component];
                break;
            case TimeOp::SplineComponent:
                scratch[i] = spline_value(in, scratch[in.a]);
                break;
            case TimeOp::PointCall:
                scratch[i] = point_value(in, t, scratch[in.a], scratch[in.b], scratch[in.c]);
                break;
            default:
                scratch[i] = apply_op(in.op, scratch[in.a], scratch[in.b], scratch[in.c]);
        }
    }
    for (std::size_t o = 0; o < outputs_.size(); ++o) outputs[o] = scratch[outputs_[o]];
}

template <class Number>
void TimeTape::evaluate(Number t, Number* outputs) const {
    constexpr std::size_t kOnStack = 64;
    if (code_.size() <= kOnStack) {
        Number scratch[kOnStack];
        evaluate(t, outputs, scratch);
    } else {
        std::vector<Number> scratch(code_.size());
        evaluate(t, outputs, scratch.data());
    }
}

PointRange TimeTape::spline_value(const Instruction& in, const PointRange& p) const {
    return PointRange(spline_value(in, p.v));
}

template void TimeTape::evaluate<double>(double, double*, double*) const;
template void TimeTape::evaluate<PointRange>(PointRange, PointRange*, PointRange*) const;
template void TimeTape::evaluate<Interval>(Interval, Interval*, Interval*) const;
template void TimeTape::evaluate<Dual>(Dual, Dual*, Dual*) const;
template void TimeTape::evaluate<IntervalJet>(IntervalJet, IntervalJet*, IntervalJet*) const;
template void TimeTape::evaluate_with<double>(double, const double*, double*, double*) const;
template void TimeTape::evaluate_with<Interval>(Interval, const Interval*, Interval*,
                                                Interval*) const;
template void TimeTape::evaluate_with<Dual>(Dual, const Dual*, Dual*, Dual*) const;
template void TimeTape::evaluate<double>(double, double*) const;
template void TimeTape::evaluate<Interval>(Interval, Interval*) const;
template void TimeTape::evaluate<Dual>(Dual, Dual*) const;
template void TimeTape::evaluate<IntervalJet>(IntervalJet, IntervalJet*) const;

}  // namespace hexant::runtime
