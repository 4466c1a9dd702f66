// julia_fractal { }: its parameter, algebra, function and settings, read
// into the object on top of the block stack (runtime/objects/julia_fractal/;
// POV-Ray's Parse_Julia_Fractal).
// Part of the actions (language/actions.hpp).
#pragma once

#include <cmath>

#include "language/actions/isosurfaces.hpp"

namespace hexant::language {

// ---------------------------------------------------------- julia_fractals

inline runtime::JuliaFractal& julia_being_read(Interpreter& st, const p::position& where) {
    auto& record = st.blocks.edit<runtime::ObjectRecord>(where, "a julia_fractal's part");
    auto* julia = std::get_if<runtime::JuliaFractal>(&record.shape);
    if (!julia) throw ValueError("this belongs in a julia_fractal");
    return *julia;
}

// POV-Ray's Parse_Vector4D: a float is all four components, a shorter
// vector is padded with 0, a colour of five is refused.
inline std::array<runtime::TimeFunction, 4> to_vector4(const Value& v, const std::string& what) {
    if (v.is<runtime::TimeFunction>()) {
        const auto f = v.as<runtime::TimeFunction>();
        return {f, f, f, f};
    }
    if (!v.is<Vector>()) throw ValueError(what + " must be a 4D vector, not a " + type_name(v));
    const Vector& vec = v.as<Vector>();
    if (vec.size > 4)
        throw ValueError(what + " must be a 4D vector <x, y, z, t>, not a " + type_name(v));
    std::array<runtime::TimeFunction, 4> out{0.0, 0.0, 0.0, 0.0};
    for (int i = 0; i < vec.size; ++i) out[static_cast<std::size_t>(i)] = vec.c[i];
    return out;
}

template <>
struct action<g::julia_open> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        runtime::ObjectRecord record;
        record.shape = runtime::JuliaFractal{};
        record.place = source_place(in);
        st.blocks.open(std::move(record));
    }
};
template <>
struct action<g::julia_parameter> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        std::vector<Value> values = st.values.close_frame();
        julia_being_read(st, in.position()).parameter =
            to_vector4(values.at(0), "the julia_fractal's parameter");
    }
};
template <>
struct action<g::julia_flag> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        using runtime::geometry::JuliaFunction;
        runtime::JuliaFractal& julia = julia_being_read(st, in.position());
        const std::string w = word(in);
        if (w == "quaternion") {
            julia.algebra = runtime::geometry::JuliaAlgebra::quaternion;
            return;
        }
        if (w == "hypercomplex") {
            julia.algebra = runtime::geometry::JuliaAlgebra::hypercomplex;
            return;
        }
        for (int f = 0; f <= static_cast<int>(JuliaFunction::reciprocal); ++f)
            if (runtime::JuliaFractal::function_word(static_cast<JuliaFunction>(f)) == w)
                julia.function = static_cast<JuliaFunction>(f);
    }
};
template <>
struct action<g::julia_pwr> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        std::vector<Value> values = st.values.close_frame();
        runtime::JuliaFractal& julia = julia_being_read(st, in.position());
        julia.function = runtime::geometry::JuliaFunction::pwr;
        julia.exponent = {to_float(values.at(0), "pwr's first exponent"),
                          to_float(values.at(1), "pwr's second exponent")};
    }
};
template <>
struct action<g::julia_setting> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        std::vector<Value> values = st.values.close_frame();
        runtime::JuliaFractal& julia = julia_being_read(st, in.position());
        const std::string w = word(in);
        const double v = to_constant(values.at(0), "a julia_fractal's " + w);
        if (!std::isfinite(v))
            throw ValueError("a julia_fractal's " + w + " must be a finite number");
        if (w == "max_iteration") {
            // POV-Ray: floor, at least 1; hexant also at most 10^6 (the
            // iteration stack's rows, per thread).
            const double n = std::floor(v);
            if (n > 1e6)
                throw ValueError("a julia_fractal's max_iteration is at most 1000000, not " +
                                 std::to_string(n));
            julia.iterations = n <= 0.0 ? 1 : static_cast<int>(n);
        } else {
            julia.precision = v;  // the step is 1 / max(P, 1), as POV-Ray's
        }
    }
};
template <>
struct action<g::julia_slice> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        std::vector<Value> values = st.values.close_frame();
        runtime::JuliaFractal& julia = julia_being_read(st, in.position());
        julia.slice = to_vector4(values.at(0), "the julia_fractal's slice");
        julia.slice_distance = to_float(values.at(1), "the julia_fractal's slice distance");
        // POV-Ray's checks, where the slice is known now (a moving one
        // leaves the shape empty at an instant where they fail).
        bool known = true;
        double p = 0.0;
        for (const auto& f : julia.slice) {
            known = known && f.is_constant();
            if (known) p += f.constant() * f.constant();
        }
        if (!known) return;
        if (std::fabs(p) < 1e-10) throw ValueError("the julia_fractal's slice vector is zero");
        if (std::fabs(julia.slice[3].constant()) < 1e-10)
            throw ValueError("the julia_fractal's slice has a zero t component");
    }
};
template <>
struct action<g::julia_block> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        if (const auto error = julia_being_read(st, in.position()).algebra_error())
            throw ValueError(*error);
        finish_object::apply(in, st);
    }
};

}  // namespace hexant::language
