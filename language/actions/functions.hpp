// User functions: function(PARAMS) { BODY } and function { internal(N) }.
// Part of the actions (language/actions.hpp).
#pragma once

#include "language/actions/arrays.hpp"
#include "language/function_internals.hpp"
#include "runtime/objects/object_error.hpp"
#include "runtime/texture/pigment_function.hpp"

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

// function { pigment { } }: F(x, y, z) is the pigment's colour, five
// components (POV-Ray's VECTFUNCT of return size 5).
template <>
struct action<g::function_pigment> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, Interpreter& st) {
        const Value v = st.values.pop();
        std::shared_ptr<const runtime::PointFunction> pigment;
        try {
            pigment = std::make_shared<const runtime::PigmentFunction>(v.as<runtime::Pigment>());
        } catch (const runtime::ObjectError& e) {
            throw UnsupportedError(std::string("a pigment function's pigment: ") + e.what());
        }
        auto f = std::make_shared<runtime::UserFunction>();
        f->parameters = {"x", "y", "z"};
        for (int c = 0; c < pigment->components(); ++c)
            f->components.push_back(runtime::TimeFunction::point_call(
                pigment, c, TimeFunction::argument(0), TimeFunction::argument(1),
                TimeFunction::argument(2)));
        st.values.push(Value{std::shared_ptr<const runtime::UserFunction>(std::move(f))});
    }
};

}  // namespace hexant::language
