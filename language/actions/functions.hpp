// User functions: function(PARAMS) { BODY } and function { internal(N) }.
// Part of the actions (language/actions.hpp).
#pragma once

#include "language/actions/arrays.hpp"
#include "language/function_internals.hpp"

namespace hexant::language {

// ------------------------------------------------------------ functions

template <>
struct action<g::function_parameter> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        const std::string name = word(in);
        for (const auto& seen : st.function_parameter_names)
            if (seen == name) throw ValueError("the parameter '" + name + "' is named twice");
        if (st.function_parameter_names.size() >= TimeFunction::kMaxArguments)
            throw ValueError("a function has at most " +
                             std::to_string(TimeFunction::kMaxArguments) + " parameters");
        st.function_parameter_names.push_back(name);
    }
};
template <>
struct action<g::function_parameters> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, Interpreter& st) {
        st.function_parameters_given = true;
    }
};
// The parameters come into scope; POV-Ray's default is (x, y, z).
template <>
struct action<g::function_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, Interpreter& st) {
        std::vector<std::string> names = std::move(st.function_parameter_names);
        if (!st.function_parameters_given) names = {"x", "y", "z"};
        st.function_parameter_names.clear();
        st.function_parameters_given = false;
        st.functions_open.push_back(std::move(names));
    }
};
template <>
struct action<g::function_body> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, Interpreter& st) {
        const TimeFunction body = to_float(st.values.pop(), "a function's body");
        auto f = std::make_shared<runtime::UserFunction>();
        f->parameters = std::move(st.functions_open.back());
        st.functions_open.pop_back();
        f->body = body;
        st.values.push(Value{std::shared_ptr<const runtime::UserFunction>(std::move(f))});
    }
};
template <>
struct action<g::function_internal_number> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, Interpreter& st) {
        const double n = to_constant(st.values.pop(), "internal()'s number");
        st.functions_open.pop_back();
        if (n != std::floor(n) || !(n >= 0.0) || n > 1e6)
            throw ValueError("internal() takes a function's number, not " + std::to_string(n));
        st.values.push(Value{internal_function(static_cast<int>(n))});
    }
};

}  // namespace hexant::language
