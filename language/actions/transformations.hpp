// Transformations: translate, rotate, scale, matrix, transform blocks and deformations.
// Part of the actions (language/actions.hpp).
#pragma once

#include "language/actions/directives.hpp"

namespace hexant::language {

// ------------------------------------------------------------ transformations

inline runtime::TransformStep make_step(TransformKind kind, const runtime::Vector3Function& v) {
    runtime::TransformStep step;
    step.kind = kind;
    step.vector = v;
    return step;
}

template <>
struct action<g::translate_step> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        st.apply_transform(
            make_step(TransformKind::Translate, to_vector3(st.values.pop(), "translate's amount")),
            in.position());
    }
};
template <>
struct action<g::rotate_step> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        st.apply_transform(
            make_step(TransformKind::Rotate, to_vector3(st.values.pop(), "rotate's angles")),
            in.position());
    }
};
template <>
struct action<g::scale_step> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        auto v = to_vector3(st.values.pop(), "scale's factors");
        // POV-Ray 3.7 warns and scales by 1 instead (parser_expressions.cpp);
        // a factor that only passes through 0 is handled where it is
        // evaluated (runtime/motion/motion.cpp, scale_factor).
        static const char* const kAxis[] = {"X", "Y", "Z"};
        for (int i = 0; i < 3; ++i)
            if (v.c[i].is_constant() && v.c[i].constant() == 0.0) {
                st.warn(in.position(), std::string("scale ") + kAxis[i] +
                                           " by 0.0: changed to 1.0, as POV-Ray does");
                v.c[i] = runtime::TimeFunction(1.0);
            }
        st.apply_transform(make_step(TransformKind::Scale, v), in.position());
    }
};
template <>
struct action<g::matrix_step> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        std::vector<Value> entries = st.values.close_frame();
        if (entries.size() != 12)
            throw ValueError("matrix needs 12 numbers, not " + std::to_string(entries.size()));
        runtime::TransformStep step;
        step.kind = TransformKind::Matrix;
        for (int i = 0; i < 12; ++i) step.matrix[i] = to_float(entries[i], "a matrix entry");
        st.apply_transform(step, in.position());
    }
};
template <>
struct action<g::transform_step> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        if (!v.is<runtime::Transform>())
            throw ValueError("transform needs a transform, not a " + type_name(v));
        for (const auto& step : v.as<runtime::Transform>().steps())
            st.apply_transform(step, in.position());
    }
};
template <>
struct action<g::transform_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        st.blocks.open(std::in_place_type<runtime::Transform>);
    }
};
template <>
struct action<g::transform_base> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        if (!v.is<runtime::Transform>())
            throw ValueError("transform { } starts with a transform, not a " + type_name(v));
        st.blocks.edit<runtime::Transform>(in.position(), "a transform") =
            v.as<runtime::Transform>();
    }
};
template <>
struct action<g::transform_inverse> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        auto& t = st.blocks.edit<runtime::Transform>(in.position(), "inverse");
        t = t.inverse();
    }
};
template <>
struct action<g::transform_block> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        Value v{std::get<runtime::Transform>(st.blocks.top())};
        st.blocks.close();
        st.values.push(std::move(v));
    }
};
template <>
struct action<g::deformation> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        const TimeFunction amount = to_float(st.values.pop(), "the deformation's amount");
        const auto axis = to_vector3(st.values.pop(), "the deformation's axis");
        const std::string name = st.values.pop_name();
        runtime::TransformStep step;
        step.kind = name == "twist"   ? TransformKind::Twist
                    : name == "taper" ? TransformKind::Taper
                                      : TransformKind::Bend;
        step.vector = axis;
        step.amount = amount;
        st.apply_deformation(step, in.position());
    }
};

}  // namespace hexant::language
