// isosurface { }: its function, container and evaluate, read into the
// object on top of the block stack (runtime/objects/isosurface/).
// Part of the actions (language/actions.hpp).
#pragma once

#include "language/actions/functions.hpp"

namespace hexant::language {

// ------------------------------------------------------------ isosurfaces

inline runtime::Isosurface& isosurface_being_read(Interpreter& st, const p::position& where) {
    auto& record = st.blocks.edit<runtime::ObjectRecord>(where, "an isosurface's part");
    auto* iso = std::get_if<runtime::Isosurface>(&record.shape);
    if (!iso) throw ValueError("this belongs in an isosurface");
    return *iso;
}

template <>
struct action<g::isosurface_open> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        runtime::ObjectRecord record;
        record.shape = runtime::Isosurface{};
        record.place = source_place(in);
        st.blocks.open(std::move(record));
    }
};
template <>
struct action<g::isosurface_function> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        const Value v = st.values.pop();
        const auto& f = *v.as<std::shared_ptr<const runtime::UserFunction>>();
        if (!f.unimplemented.empty())
            throw UnsupportedError("the internal function " + f.unimplemented +
                                   " is not implemented by hexant");
        if (!f.components.empty())
            throw ValueError(
                "an isosurface's function gives a number; this one gives a colour (pick a "
                "component: F(x, y, z).red)");
        if (f.parameters.size() > 3)
            throw ValueError("an isosurface's function is one of x, y, z; this one takes " +
                             std::to_string(f.parameters.size()) + " parameters");
        // (A part with no interval bound, a pigment function, makes the search
        // POV-Ray's, by max_gradient: runtime/objects/isosurface/.)
        isosurface_being_read(st, in.position()).function = f.body;
    }
};
template <>
struct action<g::contained_by_kind> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        st.values.push_name(word(in));
    }
};
template <>
struct action<g::contained_by_shape> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        std::vector<Value> values = st.values.close_frame();
        const std::string kind = st.values.pop_name();
        runtime::Isosurface& iso = isosurface_being_read(st, in.position());
        if (kind == "box") {
            iso.sphere_container = false;
            iso.corner1 = to_vector3(values.at(0), "contained_by box's first corner");
            iso.corner2 = to_vector3(values.at(1), "contained_by box's second corner");
        } else {
            iso.sphere_container = true;
            iso.center = to_vector3(values.at(0), "contained_by sphere's centre");
            iso.radius = to_float(values.at(1), "contained_by sphere's radius");
        }
    }
};
// POV-Ray's max_gradient estimate; hexant's search needs none.
template <>
struct action<g::isosurface_evaluate> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, Interpreter& st) {
        for (const Value& v : st.values.close_frame()) (void)to_constant(v, "evaluate's values");
    }
};
template <>
struct action<g::isosurface_block> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        if (!isosurface_being_read(st, in.position()).function)
            throw ValueError("an isosurface needs its function { }");
        finish_object::apply(in, st);
    }
};

}  // namespace hexant::language
