// Operators: unary and binary, comparisons and the logical ones.
// Part of the actions (language/actions.hpp).
#pragma once

#include "language/actions/literals.hpp"

namespace hexant::language {

// ------------------------------------------------------------ operators

template <TimeOp Op>
struct unary_action {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        st.values.push(unary_op(Op, st.values.pop()));
    }
};
template <>
struct action<g::negation> : unary_action<TimeOp::Negate> {};
template <>
struct action<g::logical_not> : unary_action<TimeOp::Not> {};

template <TimeOp Op>
struct binary_action {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        Value b = st.values.pop();
        Value a = st.values.pop();
        st.values.push(binary_op(Op, a, b));
    }
};

// A comparison of two strings is POV-Ray's Parse_Rel_String_Term: strcmp's
// sign against 0 (so "a" < "b"), through strcmp's own split over time when
// either string depends on clock. Other operands compare as numbers.
template <TimeOp Op>
struct comparison_action {
    static bool is_string(const Value& v) { return v.is<std::string>() || v.is<TimedString>(); }
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        Value b = st.values.pop();
        Value a = st.values.pop();
        if (is_string(a) && is_string(b)) {
            const std::vector<Value> args{a, b};
            std::optional<Value> timed =
                call_over_time("strcmp", args, st.domain.within(st.animation_time()),
                               st.options.limits.time_pieces, st.random);
            a = timed ? std::move(*timed) : call_builtin("strcmp", args, st.random);
            b = Value{TimeFunction(0.0)};
        }
        st.values.push(binary_op(Op, a, b));
    }
};
template <>
struct action<g::multiplication> : binary_action<TimeOp::Multiply> {};
template <>
struct action<g::division> : binary_action<TimeOp::Divide> {};
template <>
struct action<g::addition> : binary_action<TimeOp::Add> {};
template <>
struct action<g::subtraction> : binary_action<TimeOp::Subtract> {};
template <>
struct action<g::less_equal> : comparison_action<TimeOp::LessEqual> {};
template <>
struct action<g::greater_equal> : comparison_action<TimeOp::GreaterEqual> {};
template <>
struct action<g::not_equal> : comparison_action<TimeOp::NotEqual> {};
template <>
struct action<g::less> : comparison_action<TimeOp::Less> {};
template <>
struct action<g::greater> : comparison_action<TimeOp::Greater> {};
template <>
struct action<g::equal> : comparison_action<TimeOp::Equal> {};
template <>
struct action<g::logical_and> : binary_action<TimeOp::And> {};
template <>
struct action<g::logical_or> : binary_action<TimeOp::Or> {};

template <>
struct action<g::conditional_tail> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        Value c = st.values.pop();
        Value b = st.values.pop();
        Value a = st.values.pop();
        st.values.push(conditional(a, b, c));
    }
};

}  // namespace hexant::language
