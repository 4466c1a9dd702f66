#include "runtime/time/time_function.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "runtime/motion/spline.hpp"
#include "runtime/time/point_function.hpp"
#include "runtime/time/time_ops.hpp"

namespace hexant::runtime {

int arity(TimeOp op) {
    if (op == TimeOp::Constant || op == TimeOp::Clock || op == TimeOp::Argument) return 0;
    if (op <= TimeOp::SrgbDecode || op == TimeOp::SplineComponent) return 1;
    if (op <= TimeOp::Or) return 2;
    return 3;
}

const char* name(TimeOp op) {
    switch (op) {
        case TimeOp::Constant:
            return "constant";
        case TimeOp::Clock:
            return "clock";
        case TimeOp::Negate:
            return "-";
        case TimeOp::Not:
            return "!";
        case TimeOp::Abs:
            return "abs";
        case TimeOp::Sin:
            return "sin";
        case TimeOp::Cos:
            return "cos";
        case TimeOp::Tan:
            return "tan";
        case TimeOp::Asin:
            return "asin";
        case TimeOp::Acos:
            return "acos";
        case TimeOp::Atan:
            return "atan";
        case TimeOp::Sqrt:
            return "sqrt";
        case TimeOp::Exp:
            return "exp";
        case TimeOp::Log10:
            return "log";
        case TimeOp::Ln:
            return "ln";
        case TimeOp::Int:
            return "int";
        case TimeOp::Floor:
            return "floor";
        case TimeOp::Ceil:
            return "ceil";
        case TimeOp::SrgbDecode:
            return "srgb";
        case TimeOp::Add:
            return "+";
        case TimeOp::Subtract:
            return "-";
        case TimeOp::Multiply:
            return "*";
        case TimeOp::Divide:
            return "/";
        case TimeOp::Pow:
            return "pow";
        case TimeOp::Atan2:
            return "atan2";
        case TimeOp::Min:
            return "min";
        case TimeOp::Max:
            return "max";
        case TimeOp::Mod:
            return "mod";
        case TimeOp::IntDiv:
            return "div";
        case TimeOp::Less:
            return "<";
        case TimeOp::LessEqual:
            return "<=";
        case TimeOp::Equal:
            return "=";
        case TimeOp::NotEqual:
            return "!=";
        case TimeOp::GreaterEqual:
            return ">=";
        case TimeOp::Greater:
            return ">";
        case TimeOp::And:
            return "&";
        case TimeOp::Or:
            return "|";
        case TimeOp::Select:
            return "select";
        case TimeOp::Conditional:
            return "?:";
        case TimeOp::SplineComponent:
            return "spline";
        case TimeOp::PointCall:
            return "point function";
        case TimeOp::Argument:
            return "argument";
    }
    return "?";
}

static_assert(sizeof(TimeFunction) == 8);
static_assert(sizeof(void*) == 8, "a node's pointer is boxed in a double's 64 bits");

TimeFunction::TimeFunction(double value) : bits_(std::bit_cast<std::uint64_t>(value)) {
    if ((bits_ >> 48) == kNodeTag) bits_ = std::bit_cast<std::uint64_t>(std::nan(""));
}

TimeFunction::TimeFunction(const Node* node) : bits_(reinterpret_cast<std::uintptr_t>(node)) {
    // User-space addresses fit in 48 bits on x86-64 and AArch64 (4-level
    // page tables); a tagged pointer (HWASan, MTE) does not, and is refused
    // rather than lost.
    if ((bits_ >> 48) != 0) {
        delete node;
        throw std::logic_error("TimeFunction: a node's address does not fit in 48 bits");
    }
    node->references.fetch_add(1, std::memory_order_relaxed);
    bits_ |= kNodeTag << 48;
}

TimeFunction::TimeFunction(const TimeFunction& other) noexcept : bits_(other.bits_) {
    if (const Node* n = node()) n->references.fetch_add(1, std::memory_order_relaxed);
}

TimeFunction& TimeFunction::operator=(const TimeFunction& other) noexcept {
    const std::uint64_t bits = other.bits_;  // before release(): other may be *this
    if (const Node* n = other.node()) n->references.fetch_add(1, std::memory_order_relaxed);
    release();
    bits_ = bits;
    return *this;
}

TimeFunction& TimeFunction::operator=(TimeFunction&& other) noexcept {
    if (this != &other) {
        release();
        bits_ = other.bits_;
        other.bits_ = 0;
    }
    return *this;
}

void TimeFunction::release() noexcept {
    // As shared_ptr counts: the last owner's decrement acquires the others'
    // writes before the node is freed.
    if (const Node* n = node())
        if (n->references.fetch_sub(1, std::memory_order_acq_rel) == 1) delete n;
    bits_ = 0;
}

TimeFunctionTooDeep::TimeFunctionTooDeep()
    : LimitError("a function of clock nested more than " + std::to_string(kMaxTimeFunctionDepth) +
                 " operations deep (built up step by step, in a loop?)") {}

namespace {

// The node's depth from its arguments'; refuses one past the limit.
void set_depth(TimeFunction::Node& node) {
    int deepest = 0;
    for (const TimeFunction& a : node.args)
        if (const TimeFunction::Node* n = a.node()) deepest = std::max(deepest, n->depth);
    if (deepest >= kMaxTimeFunctionDepth) throw TimeFunctionTooDeep();
    node.depth = deepest + 1;
}

}  // namespace

TimeFunction TimeFunction::clock() {
    // One node for every use of clock (one per moving object in a loop).
    static const TimeFunction the_clock = [] {
        auto node = std::make_unique<Node>();
        node->op = TimeOp::Clock;
        return TimeFunction(node.release());
    }();
    return the_clock;
}

TimeFunction TimeFunction::argument(int index) {
    if (index < 0 || index >= kMaxArguments)
        throw std::out_of_range("a function has at most " + std::to_string(kMaxArguments) +
                                " parameters");
    // One node per index, as for clock: a tape computes each once.
    static const std::array<TimeFunction, kMaxArguments> arguments = [] {
        std::array<TimeFunction, kMaxArguments> all;
        for (int i = 0; i < kMaxArguments; ++i) {
            auto node = std::make_unique<Node>();
            node->op = TimeOp::Argument;
            node->component = i;
            all[i] = TimeFunction(node.release());
        }
        return all;
    }();
    return arguments[index];
}

TimeFunction TimeFunction::apply(TimeOp op, const TimeFunction& a) {
    if (a.is_constant()) return TimeFunction(apply_op(op, a.constant()));
    auto node = std::make_unique<Node>();
    node->op = op;
    node->args[0] = a;
    set_depth(*node);
    return TimeFunction(node.release());
}

TimeFunction TimeFunction::apply(TimeOp op, const TimeFunction& a, const TimeFunction& b) {
    if (a.is_constant() && b.is_constant())
        return TimeFunction(apply_op(op, a.constant(), b.constant()));
    // 0 * g is 0: the language makes it for every zero component of a
    // vector times a function of time (`rotate y * 360 * clock` is
    // <0 * f, f, 0 * f>), and a zero is what the scene means there, a constant
    // that costs no evaluation, not a function of time. (Where g is not
    // finite POV-Ray's product is NaN; g's own uses are checked there.)
    if (op == TimeOp::Multiply &&
        ((a.is_constant() && a.constant() == 0.0) || (b.is_constant() && b.constant() == 0.0)))
        return TimeFunction(0.0);
    auto node = std::make_unique<Node>();
    node->op = op;
    node->args[0] = a;
    node->args[1] = b;
    set_depth(*node);
    return TimeFunction(node.release());
}

TimeFunction TimeFunction::apply(TimeOp op, const TimeFunction& a, const TimeFunction& b,
                                 const TimeFunction& c) {
    if (a.is_constant() && b.is_constant() && c.is_constant())
        return TimeFunction(apply_op(op, a.constant(), b.constant(), c.constant()));
    // A constant condition picks its branch now, even if the branches vary.
    if (a.is_constant() && op == TimeOp::Select) return a.constant() < 0.0 ? b : c;
    if (a.is_constant() && op == TimeOp::Conditional) return pov_true(a.constant()) ? b : c;
    auto node = std::make_unique<Node>();
    node->op = op;
    node->args = {a, b, c};
    set_depth(*node);
    return TimeFunction(node.release());
}

TimeFunction TimeFunction::spline_component(std::shared_ptr<const Spline> spline, int component,
                                            const TimeFunction& t) {
    if (t.is_constant()) return TimeFunction(spline->evaluate(t.constant())[component]);
    auto node = std::make_unique<Node>();
    node->op = TimeOp::SplineComponent;
    node->args[0] = t;
    node->spline = std::move(spline);
    node->component = component;
    set_depth(*node);
    return TimeFunction(node.release());
}

TimeFunction TimeFunction::point_call(std::shared_ptr<const PointFunction> f, int component,
                                      const TimeFunction& x, const TimeFunction& y,
                                      const TimeFunction& z) {
    if (x.is_constant() && y.is_constant() && z.is_constant() && !f->depends_on_time())
        return TimeFunction(f->at(component, {x.constant(), y.constant(), z.constant()}, 0.0));
    auto node = std::make_unique<Node>();
    node->op = TimeOp::PointCall;
    node->args = {x, y, z};
    node->point_function = std::move(f);
    node->component = component;
    set_depth(*node);
    return TimeFunction(node.release());
}

double TimeFunction::operator()(double t) const {
    if (is_constant()) return constant();
    const Node& n = *node();
    switch (n.op) {
        case TimeOp::Clock:
            return t;
        case TimeOp::SplineComponent:
            return n.spline->evaluate(n.args[0](t))[n.component];
        case TimeOp::PointCall:
            return n.point_function->at(n.component, {n.args[0](t), n.args[1](t), n.args[2](t)}, t);
        case TimeOp::Argument:
            throw std::logic_error("a user function's argument read as a function of time");
        default:
            break;
    }
    switch (arity(n.op)) {
        case 1:
            return apply_op(n.op, n.args[0](t));
        case 2:
            return apply_op(n.op, n.args[0](t), n.args[1](t));
        default: {
            // Evaluate only the branch taken, as POV-Ray does.
            double a = n.args[0](t);
            bool first = n.op == TimeOp::Select ? a < 0.0 : pov_true(a);
            return first ? n.args[1](t) : n.args[2](t);
        }
    }
}

std::string TimeFunction::to_string() const {
    std::ostringstream out;
    if (is_constant()) {
        out << constant();
        return out.str();
    }
    const Node& n = *node();
    switch (n.op) {
        case TimeOp::Clock:
            return "clock";
        case TimeOp::Argument:
            if (n.component < 3) return std::string(1, static_cast<char>('x' + n.component));
            return "argument" + std::to_string(n.component + 1);
        case TimeOp::Negate:
            return "-" + n.args[0].to_string();
        case TimeOp::Not:
            return "!" + n.args[0].to_string();
        case TimeOp::SplineComponent:
            out << "spline(" << n.args[0].to_string() << ")[" << n.component << "]";
            return out.str();
        case TimeOp::PointCall:
            out << n.point_function->name() << "(" << n.args[0].to_string() << ", "
                << n.args[1].to_string() << ", " << n.args[2].to_string() << ")[" << n.component
                << "]";
            return out.str();
        case TimeOp::Conditional:
            return "(" + n.args[0].to_string() + " ? " + n.args[1].to_string() + " : " +
                   n.args[2].to_string() + ")";
        default:
            break;
    }
    if (n.op >= TimeOp::Add && n.op <= TimeOp::Divide) {
        return "(" + n.args[0].to_string() + " " + name(n.op) + " " + n.args[1].to_string() + ")";
    }
    if (n.op >= TimeOp::Less && n.op <= TimeOp::Or) {
        return "(" + n.args[0].to_string() + " " + name(n.op) + " " + n.args[1].to_string() + ")";
    }
    out << name(n.op) << "(";
    for (int i = 0; i < arity(n.op); ++i) out << (i ? ", " : "") << n.args[i].to_string();
    out << ")";
    return out.str();
}

namespace {

// Visits f's nodes children first, each once, without recursion (bodies can
// be deep); visit(node) sees every argument's node visited before it.
template <class Visit>
void post_order(const TimeFunction& f, Visit&& visit) {
    if (f.is_constant()) return;
    std::unordered_set<const TimeFunction::Node*> done;
    std::vector<const TimeFunction::Node*> stack{f.node()};
    while (!stack.empty()) {
        const TimeFunction::Node* node = stack.back();
        if (done.count(node)) {
            stack.pop_back();
            continue;
        }
        bool ready = true;
        for (int i = 0; i < arity(node->op); ++i) {
            const TimeFunction::Node* arg = node->args[i].node();
            if (arg != nullptr && !done.count(arg)) {
                stack.push_back(arg);
                ready = false;
            }
        }
        if (!ready) continue;
        visit(node);
        done.insert(node);
        stack.pop_back();
    }
}

}  // namespace

TimeFunction substitute_arguments(const TimeFunction& f,
                                  const std::vector<TimeFunction>& arguments) {
    if (f.is_constant()) return f;
    std::unordered_map<const TimeFunction::Node*, TimeFunction> made;
    const auto rebuilt = [&](const TimeFunction& a) {
        return a.is_constant() ? a : made.at(a.node());
    };
    post_order(f, [&](const TimeFunction::Node* node) {
        TimeFunction out;
        switch (node->op) {
            case TimeOp::Argument:
                out = arguments.at(static_cast<std::size_t>(node->component));
                break;
            case TimeOp::Clock:
                out = TimeFunction::clock();
                break;
            case TimeOp::SplineComponent:
                out = TimeFunction::spline_component(node->spline, node->component,
                                                     rebuilt(node->args[0]));
                break;
            case TimeOp::PointCall:
                out = TimeFunction::point_call(node->point_function, node->component,
                                               rebuilt(node->args[0]), rebuilt(node->args[1]),
                                               rebuilt(node->args[2]));
                break;
            default:
                switch (arity(node->op)) {
                    case 1:
                        out = TimeFunction::apply(node->op, rebuilt(node->args[0]));
                        break;
                    case 2:
                        out = TimeFunction::apply(node->op, rebuilt(node->args[0]),
                                                  rebuilt(node->args[1]));
                        break;
                    default:
                        out = TimeFunction::apply(node->op, rebuilt(node->args[0]),
                                                  rebuilt(node->args[1]), rebuilt(node->args[2]));
                }
        }
        made.emplace(node, std::move(out));
    });
    return made.at(f.node());
}

bool uses_arguments(const TimeFunction& f) {
    bool found = false;
    post_order(
        f, [&](const TimeFunction::Node* node) { found = found || node->op == TimeOp::Argument; });
    return found;
}

TimeFunction operator+(const TimeFunction& a, const TimeFunction& b) {
    if (a.is_constant() && a.constant() == 0.0) return b;
    if (b.is_constant() && b.constant() == 0.0) return a;
    return TimeFunction::apply(TimeOp::Add, a, b);
}
TimeFunction operator-(const TimeFunction& a, const TimeFunction& b) {
    if (b.is_constant() && b.constant() == 0.0) return a;
    return TimeFunction::apply(TimeOp::Subtract, a, b);
}
TimeFunction operator*(const TimeFunction& a, const TimeFunction& b) {
    if (a.is_constant() && a.constant() == 1.0) return b;
    if (b.is_constant() && b.constant() == 1.0) return a;
    return TimeFunction::apply(TimeOp::Multiply, a, b);
}
TimeFunction operator/(const TimeFunction& a, const TimeFunction& b) {
    if (b.is_constant() && b.constant() == 1.0) return a;
    return TimeFunction::apply(TimeOp::Divide, a, b);
}
TimeFunction operator-(const TimeFunction& a) {
    return TimeFunction::apply(TimeOp::Negate, a);
}

}  // namespace hexant::runtime
