// User functions: function(PARAMS) { BODY } and function { internal(N) }.
// Part of the actions (language/actions.hpp).
#pragma once

#include "language/actions/arrays.hpp"
#include "language/function_internals.hpp"
#include "runtime/motion/transform_function.hpp"
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

// function { transform { } }: F(x, y, z) is the point transformed, three
// components (POV-Ray's VECTFUNCT of return size 3): a fixed transform's
// affine map written out, one that moves with clock evaluated at the call's
// time (runtime/motion/transform_function.hpp).
template <>
struct action<g::function_transform> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, Interpreter& st) {
        const Value v = st.values.pop();
        if (!v.is<runtime::Transform>())
            throw ValueError("function { transform { } } needs a transform, not a " + type_name(v));
        const runtime::Transform& transform = v.as<runtime::Transform>();
        if (transform.has_deformation())
            throw ValueError("a transform function's transform may not twist, taper or bend");
        auto f = std::make_shared<runtime::UserFunction>();
        f->parameters = {"x", "y", "z"};
        const TimeFunction x = TimeFunction::argument(0), y = TimeFunction::argument(1),
                           z = TimeFunction::argument(2);
        if (!transform.depends_on_time()) {
            const glm::dmat4 m = transform.matrix_at(0.0);
            for (int c = 0; c < 3; ++c)
                f->components.push_back(m[0][c] * x + m[1][c] * y + m[2][c] * z + m[3][c]);
        } else {
            const auto moving = std::make_shared<const runtime::TransformFunction>(transform);
            for (int c = 0; c < 3; ++c)
                f->components.push_back(TimeFunction::point_call(moving, c, x, y, z));
        }
        st.values.push(Value{std::shared_ptr<const runtime::UserFunction>(std::move(f))});
    }
};

// function { pattern { } }: F(x, y, z) is the pattern's value, read through
// a grey ramp (exact for values in [0, 1]: 0 + v * (1 - 0)), everything
// else of a pigment's (transforms, warps, turbulence) as written.
template <>
struct action<g::function_pattern_value_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, Interpreter& st) {
        st.blocks.open(std::in_place_type<runtime::Pigment>);
    }
};
template <>
struct action<g::function_pattern_value> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, Interpreter& st) {
        auto& written = st.blocks.edit<runtime::Pigment>(in.position(), "a pattern function");
        if (written.patterned->kind == nullptr)
            throw ValueError("a pattern function needs its pattern: function { pattern { bozo } }");
        close_pigment(written);
        runtime::Pigment pigment = std::move(written);
        st.blocks.close();
        pigment.pigment_map.clear();
        runtime::ColourMapEntry black, white;
        black.value = 0.0;
        white.value = 1.0;
        for (std::size_t c = 0; c < 3; ++c) white.colour.c[c] = 1.0;
        pigment.colour_map.entries.clear();
        pigment.colour_map.entries.push_back(black);
        pigment.colour_map.entries.push_back(white);
        std::shared_ptr<const runtime::PointFunction> value;
        try {
            value = std::make_shared<const runtime::PigmentFunction>(pigment, "pattern function");
        } catch (const runtime::ObjectError& e) {
            throw UnsupportedError(std::string("a pattern function's pattern: ") + e.what());
        }
        auto f = std::make_shared<runtime::UserFunction>();
        f->parameters = {"x", "y", "z"};
        f->body = TimeFunction::point_call(value, 0, TimeFunction::argument(0),
                                           TimeFunction::argument(1), TimeFunction::argument(2));
        st.values.push(Value{std::shared_ptr<const runtime::UserFunction>(std::move(f))});
    }
};

}  // namespace hexant::language
