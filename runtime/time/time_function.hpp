// A scalar function of animation time t, built symbolically from `clock`.
//
// The language builds these while it parses: arithmetic on a value that
// depends on `clock` makes a new node instead of a number. Anything that does
// not depend on `clock` folds to a constant at once, so a static scene holds
// only constants and pays nothing for time.
#pragma once

#include <array>
#include <atomic>
#include <bit>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "runtime/time/limit_error.hpp"

namespace hexant::runtime {

class Spline;
class PointFunction;

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
    // PointCall(x, y, z) = point_function(x, y, z, t)[component]: a pigment
    // function's channel, a noise (runtime/time/point_function.hpp).
    PointCall,
    // A user function's argument number `component` (x, y, z are 0, 1, 2
    // in POV-Ray's default function(x, y, z)): nullary, as clock. Only a
    // user function's body holds it (runtime/time/user_function.hpp); a
    // call substitutes the arguments, and the tape of an isosurface's
    // function is evaluated with them.
    Argument,
};

int arity(TimeOp op);
const char* name(TimeOp op);

// Eight bytes, a double or a node (a scene of 10^5 moving objects holds
// some 40 of these per object: at 24 bytes, as a double beside a
// shared_ptr, they were a third of what parsing it held). A node is a
// pointer boxed in a NaN, as JavaScript engines and LuaJIT box theirs: the
// bit pattern 0x7FF4 in the top 16 bits (a signalling NaN, which no
// arithmetic makes) with the pointer in the low 48. A constant whose bits
// happen to read so is stored as the quiet NaN instead (the payload of a
// NaN has no meaning in the language). Nodes count their references.
class TimeFunction {
  public:
    // A constant function.
    TimeFunction(double value = 0.0);  // NOLINT: implicit on purpose, numbers are functions
    static TimeFunction clock();
    // Argument number `index` of a user function (0 <= index < kMaxArguments).
    static TimeFunction argument(int index);
    static constexpr int kMaxArguments = 64;

    TimeFunction(const TimeFunction& other) noexcept;
    TimeFunction(TimeFunction&& other) noexcept : bits_(other.bits_) { other.bits_ = 0; }
    TimeFunction& operator=(const TimeFunction& other) noexcept;
    TimeFunction& operator=(TimeFunction&& other) noexcept;
    ~TimeFunction() { release(); }

    static TimeFunction apply(TimeOp op, const TimeFunction& a);
    static TimeFunction apply(TimeOp op, const TimeFunction& a, const TimeFunction& b);
    static TimeFunction apply(TimeOp op, const TimeFunction& a, const TimeFunction& b,
                              const TimeFunction& c);
    static TimeFunction spline_component(std::shared_ptr<const Spline> spline, int component,
                                         const TimeFunction& t);
    // Component `component` of f at the point (x, y, z), at the time the
    // function is evaluated; a number when the point is and f does not
    // move.
    static TimeFunction point_call(std::shared_ptr<const PointFunction> f, int component,
                                   const TimeFunction& x, const TimeFunction& y,
                                   const TimeFunction& z);

    bool is_constant() const { return (bits_ >> 48) != kNodeTag; }
    // The value of a constant function; only valid when is_constant().
    double constant() const { return std::bit_cast<double>(bits_); }
    bool depends_on_time() const { return !is_constant(); }

    // The value at time t.
    double operator()(double t) const;

    // A readable form, e.g. "(360 * clock)", for summaries and messages.
    std::string to_string() const;

    struct Node;
    // The node, or null for a constant.
    const Node* node() const {
        return is_constant() ? nullptr : reinterpret_cast<const Node*>(bits_ & kPointerBits);
    }

  private:
    static constexpr std::uint64_t kNodeTag = 0x7FF4;
    static constexpr std::uint64_t kPointerBits = (std::uint64_t(1) << 48) - 1;

    // Takes one reference to `node` (made with new, references counted from 0).
    explicit TimeFunction(const Node* node);
    void release() noexcept;

    std::uint64_t bits_;
};

struct TimeFunction::Node {
    TimeOp op = TimeOp::Constant;
    int depth = 1;      // of the tree below: 1 + its deepest argument's
    int component = 0;  // for SplineComponent, PointCall
    mutable std::atomic<std::uint32_t> references{0};
    std::array<TimeFunction, 3> args;
    std::shared_ptr<const Spline> spline;                 // for SplineComponent
    std::shared_ptr<const PointFunction> point_function;  // for PointCall
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

// f with each Argument(k) replaced by arguments[k] (a user function's call:
// its body with the call's arguments in place), folding what becomes
// constant. Shared sub-functions stay shared. Throws std::out_of_range for
// an argument index past arguments' end.
TimeFunction substitute_arguments(const TimeFunction& f,
                                  const std::vector<TimeFunction>& arguments);
// Whether f holds an Argument (a user function's body that reads x, y, z).
bool uses_arguments(const TimeFunction& f);

TimeFunction operator+(const TimeFunction& a, const TimeFunction& b);
TimeFunction operator-(const TimeFunction& a, const TimeFunction& b);
TimeFunction operator*(const TimeFunction& a, const TimeFunction& b);
TimeFunction operator/(const TimeFunction& a, const TimeFunction& b);
TimeFunction operator-(const TimeFunction& a);

}  // namespace hexant::runtime
