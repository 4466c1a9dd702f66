// Lights: light_source and its items.
// Part of the actions (language/actions.hpp).
#pragma once

#include "language/actions/meshes.hpp"

namespace hexant::language {

// ------------------------------------------------------------ lights

template <>
struct action<g::light_arguments> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        std::vector<Value> args = st.values.close_frame();
        // light_source { L modifiers }: a copy of the declared light, as
        // POV-Ray's Parse_Light_Source starts from a LIGHT_SOURCE_ID.
        if (args[0].is<runtime::LightRecord>()) {
            if (args.size() > 1)
                throw ValueError("a declared light_source takes modifiers after it, not a colour");
            st.blocks.open(args[0].as<runtime::LightRecord>());
            return;
        }
        runtime::LightRecord light;
        light.position = to_vector3(args[0], "the light's position");
        if (args.size() > 1)
            light.colour = to_colour(args[1], "the light's colour");
        else
            light.colour.c = {1.0, 1.0, 1.0, 0.0, 0.0};  // POV-Ray's default: white
        (void)in;
        st.blocks.open(std::move(light));
    }
};
template <>
struct action<g::light_flag> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        const std::string w = word(in);
        auto& light = st.blocks.edit<runtime::LightRecord>(in.position(), w.c_str());
        // (POV-Ray's Parse_Light_Source: the kind's keyword sets its
        // defaults, so radius, falloff and tightness come after it.)
        // shadowless is POV-Ray's fill light, a type of its own: it turns
        // a spotlight or cylinder back into a plain light, and either
        // keyword after it turns it into theirs, with shadows.
        if (w == "shadowless") {
            light.shadowless = true;
            light.kind = runtime::LightKind::Point;
        } else if (w == "spotlight") {
            light.shadowless = false;
            light.kind = runtime::LightKind::Spotlight;
            light.radius = 30.0;
            light.falloff = 45.0;
            light.tightness = 0.0;
        } else if (w == "cylinder") {
            light.shadowless = false;
            light.kind = runtime::LightKind::Cylinder;
            light.radius = 0.75;
            light.falloff = 1.0;
            light.tightness = 0.0;
            light.parallel = true;
        } else if (w == "parallel")
            light.parallel = true;
        else if (w == "jitter")
            light.jitter = true;
        else if (w == "circular")
            light.circular = true;
        else if (w == "orient")
            light.orient = true;
    }
};
template <>
struct action<g::light_setting> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        const std::string name = st.values.pop_name();
        auto& light = st.blocks.edit<runtime::LightRecord>(in.position(), name.c_str());
        const bool shaped = light.kind != runtime::LightKind::Point;
        // (POV-Ray refuses these on a standard light, its Not_With.)
        if (((name == "radius" || name == "falloff" || name == "tightness") && !shaped) ||
            (name == "point_at" && !shaped && !light.parallel))
            throw ValueError("'" + name + "' needs a spotlight or cylinder light" +
                             (name == "point_at" ? " or a parallel one" : "") +
                             " (say so before it)");
        if (name == "point_at")
            light.point_at = to_vector3(v, name);
        else if (name == "radius")
            light.radius = to_float(v, name);
        else if (name == "falloff")
            light.falloff = to_float(v, name);
        else if (name == "tightness")
            light.tightness = to_float(v, name);
        else if (name == "fade_distance")
            light.fade_distance = to_float(v, name);
        else if (name == "fade_power")
            light.fade_power = to_float(v, name);
        else if (name == "media_attenuation")
            light.media_attenuation = runtime::pov_true(to_constant(v, name));
        else if (name == "media_interaction")
            light.media_interaction = runtime::pov_true(to_constant(v, name));
        // adaptive: POV-Ray's shortcut to the area grid's average, which
        // hexant samples whole. Read, no effect.
    }
};
template <>
struct action<g::area_light> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        std::vector<Value> given = st.values.close_frame();
        auto& light = st.blocks.edit<runtime::LightRecord>(in.position(), "area_light");
        runtime::AreaLight area;
        area.axis1 = to_vector3(given.at(0), "area_light's first axis");
        area.axis2 = to_vector3(given.at(1), "area_light's second axis");
        // (Lights along each axis: POV-Ray truncates to whole numbers and
        // refuses 0. hexant samples the grid, never stores it: 2^20 a side
        // is no limit a scene meets.)
        area.size1 =
            int(checked_integer(std::trunc(to_constant(given.at(2), "area_light's first size")),
                                "area_light's first size", 1, 1 << 20));
        area.size2 =
            int(checked_integer(std::trunc(to_constant(given.at(3), "area_light's second size")),
                                "area_light's second size", 1, 1 << 20));
        light.area = std::move(area);
    }
};
template <>
struct action<g::projected_through_base> : action<g::object_base> {};
template <>
struct action<g::light_projected_through> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        // (The object's block, closed as object { } closes; the light's
        // transforms move it with the light: Interpreter::add_light.)
        finish_object::apply(in, st);
        Value v = st.values.pop();
        if (!v.is<runtime::ObjectPtr>())
            throw ValueError("projected_through { } needs an object, not a " + type_name(v));
        auto& light = st.blocks.edit<runtime::LightRecord>(in.position(), "projected_through");
        // (POV-Ray keeps the last one written.)
        light.projected_through = v.as<runtime::ObjectPtr>();
    }
};
// POV-Ray's Parse_Light_Source: the object is moved to the light's centre,
// then its modifiers apply (a scale inside looks_like { } scales about the
// origin, after the move), then the light's own transforms
// (Interpreter::add_light).
template <>
struct action<g::looks_like_base> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        action<g::object_base>::apply(in, st);
        const Block* around = st.blocks.around_top();
        if (around == nullptr || !std::holds_alternative<runtime::LightRecord>(*around) ||
            !std::holds_alternative<runtime::ObjectRecord>(st.blocks.top()))
            throw ValueError("looks_like { } needs an object");
        const auto& light = std::get<runtime::LightRecord>(*around);
        std::get<runtime::ObjectRecord>(st.blocks.top())
            .transform.append(runtime::TransformStep{
                runtime::TransformKind::Translate, light.position, {}, {}, false});
    }
};
template <>
struct action<g::light_looks_like> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        // (The object's block, closed as object { } closes.)
        finish_object::apply(in, st);
        Value v = st.values.pop();
        if (!v.is<runtime::ObjectPtr>())
            throw ValueError("looks_like { } needs an object, not a " + type_name(v));
        auto& light = st.blocks.edit<runtime::LightRecord>(in.position(), "looks_like");
        if (light.looks_like)
            throw ValueError("only one looks_like is allowed per light_source (POV-Ray's rule)");
        light.looks_like = v.as<runtime::ObjectPtr>();
    }
};
template <>
struct action<g::light_block> : finish_object {};

}  // namespace hexant::language
