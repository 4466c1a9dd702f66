// bicubic_patch { }: its type, flatness, steps, uv_vectors and 16 control
// points, read into the object on top of the block stack
// (runtime/objects/bicubic_patch/; POV-Ray's Parse_Bicubic_Patch).
// Part of the actions (language/actions.hpp).
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

#include "language/actions/julia_fractals.hpp"

namespace hexant::language {

// ---------------------------------------------------------- bicubic patches

// A number as a message shows it (1, 2.5, -3).
inline std::string bicubic_number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

inline runtime::BicubicPatch& bicubic_being_read(Interpreter& st, const p::position& where) {
    auto& record = st.blocks.edit<runtime::ObjectRecord>(where, "a bicubic_patch's part");
    auto* patch = std::get_if<runtime::BicubicPatch>(&record.shape);
    if (!patch) throw ValueError("this belongs in a bicubic_patch");
    return *patch;
}

template <>
struct action<g::bicubic_open> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        runtime::ObjectRecord record;
        runtime::BicubicPatch patch;
        patch.type = -1;  // until read: POV-Ray has no default type
        record.shape = std::move(patch);
        record.place = source_place(in);
        st.blocks.open(std::move(record));
    }
};
template <>
struct action<g::bicubic_setting> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        std::vector<Value> values = st.values.close_frame();
        runtime::BicubicPatch& patch = bicubic_being_read(st, in.position());
        const std::string w = word(in);
        const double v = to_constant(values.at(0), "a bicubic_patch's " + w);
        if (!std::isfinite(v))
            throw ValueError("a bicubic_patch's " + w + " must be a finite number");
        // POV-Ray reads type and the steps as (int) casts: toward zero.
        const double whole = std::trunc(v);
        if (w == "type") {
            if (whole < 0.0)
                throw ValueError("a bicubic_patch's type is 0 or 1, not " + bicubic_number(v) +
                                 " (POV-Ray: undefined bicubic patch type)");
            if (whole > 1.0)
                throw ValueError("a bicubic_patch's type is 0 or 1, not " + bicubic_number(whole) +
                                 " (POV-Ray 3.7 warns that the type is no longer supported "
                                 "and renders type 1: write type 1)");
            patch.type = static_cast<int>(whole);
        } else if (w == "u_steps" || w == "v_steps") {
            if (whole < 0.0 || whole > runtime::BicubicPatch::kMaxSteps)
                throw ValueError("a bicubic_patch's " + w + " is a whole number from 0 to " +
                                 std::to_string(runtime::BicubicPatch::kMaxSteps) + ", not " +
                                 bicubic_number(v));
            (w == "u_steps" ? patch.u_steps : patch.v_steps) = static_cast<int>(whole);
        } else if (w == "flatness") {
            patch.flatness = v;
        }
        // accuracy: read, as POV-Ray reads it; nothing uses it.
    }
};
template <>
struct action<g::bicubic_uv_vectors> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        std::vector<Value> values = st.values.close_frame();
        runtime::BicubicPatch& patch = bicubic_being_read(st, in.position());
        static constexpr const char* which[4] = {"first", "second", "third", "fourth"};
        for (std::size_t k = 0; k < 4; ++k)
            patch.uv_corners[k] = to_vector2(
                values.at(k), std::string("the bicubic_patch's ") + which[k] + " uv vector");
    }
};
template <>
struct action<g::bicubic_points> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        std::vector<Value> values = st.values.close_frame();
        runtime::BicubicPatch& patch = bicubic_being_read(st, in.position());
        if (patch.type < 0)
            throw ValueError(
                "a bicubic_patch needs its type before its control points: type 0 or type 1");
        if (values.size() != 16)
            throw ValueError("a bicubic_patch has 16 control points (4 rows of 4), but " +
                             std::to_string(values.size()) +
                             (values.size() == 1 ? " was" : " were") + " given");
        for (std::size_t k = 0; k < 16; ++k)
            patch.points[k] =
                to_vector3(values[k], "the bicubic_patch's control point " + std::to_string(k + 1) +
                                          " (row " + std::to_string(k / 4 + 1) + ")");
    }
};
template <>
struct action<g::bicubic_block> : finish_object {};

}  // namespace hexant::language
