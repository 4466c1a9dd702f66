// A scalar function of animation time t, built symbolically from `clock`.
//
// The language builds these while it parses: arithmetic on a value that
// depends on `clock` makes a new node instead of a number. Anything that does
// not depend on `clock` folds to a constant at once, so a static scene holds
// only constants and pays nothing for time.
#pragma once

#include <array>
#include <memory>
#include <string>

#include "runtime/limit_error.hpp"

namespace hexant::runtime {

class Spline;

// The operations a time function is made of. Each has a fixed arity
// (see arity()); evaluation of one operation lives in time_ops.hpp.
enum class TimeOp {
    Constant,
    Clock,
    // unary
    Negate,
    Not,
    Abs,
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan,
    Sqrt,
    Exp,
    Log10,
    Ln,
    Int,
    Floor,
    Ceil,
    SrgbDecode,
    // binary
    Add,
    Subtract,
    Multiply,
    Divide,
    Pow,
    Atan2,
    Min,
    Max,
    Mod,
    IntDiv,
    Less,
    LessEqual,
    Equal,
    NotEqual,
    GreaterEqual,
    Greater,
    And,
    Or,
    // ternary: select(a, b, c) with POV-Ray's meaning (a < 0 ? b : c),
    // Conditional(a, b, c) is a ? b : c.
    Select,
    Conditional,
    // spline component: SplineComponent(t) = spline(t)[component]
    SplineComponent,
};

int arity(TimeOp op);
const char* name(TimeOp op);

class TimeFunction {
public:
    // A constant function.
    TimeFunction(double value = 0.0);  // NOLINT: implicit on purpose, numbers are functions
    static TimeFunction clock();

    static TimeFunction apply(TimeOp op, const TimeFunction& a);
    static TimeFunction apply(TimeOp op, const TimeFunction& a, const TimeFunction& b);
    static TimeFunction apply(TimeOp op, const TimeFunction& a, const TimeFunction& b,
                              const TimeFunction& c);
    static TimeFunction spline_component(std::shared_ptr<const Spline> spline, int component,
                                         const TimeFunction& t);

    bool is_constant() const { return node_ == nullptr; }
    // The value of a constant function; only valid when is_constant().
    double constant() const { return value_; }
    bool depends_on_time() const { return !is_constant(); }

    // The value at time t.
    double operator()(double t) const;

    // A readable form, e.g. "(360 * clock)", for summaries and messages.
    std::string to_string() const;

    struct Node;
    const Node* node() const { return node_.get(); }

private:
    explicit TimeFunction(std::shared_ptr<const Node> node);

    double value_ = 0.0;
    std::shared_ptr<const Node> node_;  // null for constants
};

struct TimeFunction::Node {
    TimeOp op;
    std::array<TimeFunction, 3> args;
    std::shared_ptr<const Spline> spline;  // for SplineComponent
    int component = 0;                     // for SplineComponent
    int depth = 1;                         // of the tree below: 1 + its deepest argument's
};

// Functions of time are trees, and reading, compiling, printing and freeing
// them recurse down the tree: one nested deeper than this (an expression of
// clock built up step by step, `#declare X = X + clock` in a loop of 10^5
// iterations, say) is refused where it is made, before any of them could
// run out of stack: at this depth, reading, checking, dumping and rendering
// a scene stay within a 1 MB stack (tried with ulimit -s 1024).
inline constexpr int kMaxTimeFunctionDepth = 10000;
struct TimeFunctionTooDeep : LimitError {
    TimeFunctionTooDeep();
};

TimeFunction operator+(const TimeFunction& a, const TimeFunction& b);
TimeFunction operator-(const TimeFunction& a, const TimeFunction& b);
TimeFunction operator*(const TimeFunction& a, const TimeFunction& b);
TimeFunction operator/(const TimeFunction& a, const TimeFunction& b);
TimeFunction operator-(const TimeFunction& a);

}  // namespace hexant::runtime
