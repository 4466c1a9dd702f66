// cubic, quartic, poly and polynomial: their order and coefficients, read
// into the object on top of the block stack (runtime/objects/poly/).
// Part of the actions (language/actions.hpp).
#pragma once

#include "language/actions/bicubic_patches.hpp"

namespace hexant::language {

// ------------------------------------------------------------ polys

inline runtime::PolySurface& poly_being_read(Interpreter& st, const p::position& where) {
    auto& record = st.blocks.edit<runtime::ObjectRecord>(where, "a polynomial's part");
    runtime::PolySurface* poly = std::visit(
        [](auto& shape) -> runtime::PolySurface* {
            if constexpr (std::is_base_of_v<runtime::PolySurface, std::decay_t<decltype(shape)>>)
                return &shape;
            else
                return nullptr;
        },
        record.shape);
    if (!poly) throw ValueError("this belongs in a poly");
    return *poly;
}

// The order's coefficients, all zero (polynomial's terms are added to them).
inline void set_poly_order(runtime::PolySurface& poly, double order) {
    if (order != std::floor(order) || order < 2 || order > runtime::kMaxPolyOrder)
        throw ValueError("a poly's order is a whole number from 2 to " +
                         std::to_string(runtime::kMaxPolyOrder) + " here, not " +
                         std::to_string(order) +
                         (order > runtime::kMaxPolyOrder && order <= 35
                              ? " (POV-Ray reads up to 35; hexant's root solver stops at " +
                                    std::to_string(runtime::kMaxPolyOrder) + ")"
                              : ""));
    poly.order = static_cast<int>(order);
    poly.coefficients.assign(static_cast<std::size_t>(runtime::poly_term_count(poly.order)),
                             TimeFunction(0.0));
}

template <>
struct action<g::poly_open> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        const std::string kind = word(in);
        runtime::ObjectRecord record;
        if (kind == "cubic") {
            runtime::Cubic c;
            set_poly_order(c, 3);
            record.shape = std::move(c);
        } else if (kind == "quartic") {
            runtime::Quartic q;
            set_poly_order(q, 4);
            record.shape = std::move(q);
        } else if (kind == "poly") {
            record.shape = runtime::Poly{};
        } else {
            record.shape = runtime::Polynomial{};
        }
        record.place = source_place(in);
        st.blocks.open(std::move(record));
    }
};
template <>
struct action<g::poly_order> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        const double order = to_constant(st.values.pop(), "a poly's order");
        runtime::PolySurface& poly = poly_being_read(st, in.position());
        if (poly.order != 0)
            throw ValueError("a cubic or quartic has its order; write only its coefficients");
        set_poly_order(poly, order);
    }
};
template <>
struct action<g::poly_coefficients> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        std::vector<Value> values = st.values.close_frame();
        runtime::PolySurface& poly = poly_being_read(st, in.position());
        if (poly.order == 0) throw ValueError("a poly needs its order before its coefficients");
        if (values.size() != poly.coefficients.size())
            throw ValueError("a polynomial of order " + std::to_string(poly.order) + " has " +
                             std::to_string(poly.coefficients.size()) + " coefficients, not " +
                             std::to_string(values.size()));
        for (std::size_t n = 0; n < values.size(); ++n)
            poly.coefficients[n] = to_float(values[n], "a poly's coefficient");
    }
};
template <>
struct action<g::polynomial_term> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        std::vector<Value> values = st.values.close_frame();
        runtime::PolySurface& poly = poly_being_read(st, in.position());
        if (poly.order == 0) throw ValueError("a polynomial needs its order before its terms");
        int e[3];
        for (int i = 0; i < 3; ++i) {
            const double v = to_constant(values.at(static_cast<std::size_t>(i)), "xyz()'s power");
            if (v != std::floor(v) || v < 0 || v > poly.order)
                throw ValueError("xyz()'s powers are whole numbers from 0 to the order, not " +
                                 std::to_string(v));
            e[i] = static_cast<int>(v);
        }
        if (e[0] + e[1] + e[2] > poly.order)
            throw ValueError("the term's powers add up to more than the order " +
                             std::to_string(poly.order));
        const int index = runtime::poly_term_index(poly.order, e[0], e[1], e[2]);
        poly.coefficients[static_cast<std::size_t>(index)] =
            to_float(values.at(3), "the term's coefficient");
    }
};
template <>
struct action<g::poly_block> : finish_object {};

}  // namespace hexant::language
