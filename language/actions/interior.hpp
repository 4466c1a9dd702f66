// interior { }: ior, dispersion, fade_*, caustics and media
// (runtime::Interior), read as POV-Ray 3.7's Parse_Interior reads them.
// Part of the actions (language/actions.hpp).
#pragma once

#include "language/actions/media.hpp"

namespace hexant::language {

template <>
struct action<g::interior_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        st.blocks.open(std::in_place_type<runtime::Interior>);
    }
};
template <>
struct action<g::interior_base> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        if (!v.is<runtime::Interior>())
            throw ValueError("interior { } starts with an interior, not a " + type_name(v));
        st.blocks.edit<runtime::Interior>(in.position(), "an interior") = v.as<runtime::Interior>();
    }
};
template <>
struct action<g::fade_setting_name> : name_action {};
template <>
struct action<g::fade_setting_value> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        const std::string name = st.values.pop_name();
        auto& interior = st.blocks.edit<runtime::Interior>(in.position(), name.c_str());
        if (name == "fade_distance") {
            interior.fade_distance = to_float(v, name);
        } else if (name == "fade_power") {
            interior.fade_power = to_float(v, name);
        } else if (name == "caustics") {
            interior.caustics = to_float(v, name);
        } else {
            interior.fade_colour = to_colour(v, name);
            interior.fade_colour.c[3] = interior.fade_colour.c[4] = 0.0;
        }
    }
};
template <>
struct action<g::ior_setting> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        auto& interior = st.blocks.edit<runtime::Interior>(in.position(), "ior");
        interior.ior = to_float(st.values.pop(), "ior");
        interior.ior_written = true;
    }
};
template <>
struct action<g::interior_block> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        Value v{std::get<runtime::Interior>(st.blocks.top())};
        st.blocks.close();
        st.values.push(std::move(v));
    }
};

template <>
struct action<g::dispersion_setting_name> : name_action {};
template <>
struct action<g::dispersion_setting_value> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        const std::string name = st.values.pop_name();
        auto& interior = st.blocks.edit<runtime::Interior>(in.position(), name.c_str());
        if (name == "dispersion_samples") {
            interior.dispersion_samples =
                media_count(v, name, 2, "dispersion_samples must be at least 2 (POV-Ray's rule)");
            // (Each band is a ray where a ray meets the surface unsampled.)
            if (interior.dispersion_samples > 1000)
                throw ValueError("dispersion_samples above 1000 (each band is a ray of its own)");
            return;
        }
        // (A band's ior is the written one times a power of D: D must be
        // positive, or every ior would be NaN.)
        interior.dispersion = to_float(v, name);
        if (interior.dispersion.is_constant() && !(interior.dispersion.constant() > 0.0))
            throw ValueError("dispersion must be above 0 (1 is none), not " +
                             std::to_string(interior.dispersion.constant()));
    }
};

}  // namespace hexant::language
