// Warps: warp { } in a pigment, normal or texture, one warp a block
// (POV-Ray 3.7's Parse_Warp; runtime/texture/pattern/warps/).
// Part of the actions (language/actions.hpp).
#pragma once

#include <climits>

#include "language/actions/patterns.hpp"

namespace hexant::language {

// The warp being written: the last of its pattern's.
inline runtime::pattern::Warp& warp_being_written(Interpreter& st, const p::position& at) {
    return pattern_slot(st, at, "warp").pattern.warps.back();
}
// Its repeat, black hole or mapping record (the grammar reads only the
// settings of the kind its keyword began).
template <class Record>
Record& point_warp(Interpreter& st, const p::position& at) {
    return std::get<Record>(*warp_being_written(st, at).point);
}

// An orientation is made unit where it is read (POV-Ray's VNormalizeEq);
// a zero vector would make every coordinate NaN.
inline runtime::Vector3Function warp_orientation(const Value& v, const std::string& what) {
    runtime::Vector3Function o = to_vector3(v, what);
    if (!o.depends_on_time() && o.c[0].constant() == 0.0 && o.c[1].constant() == 0.0 &&
        o.c[2].constant() == 0.0)
        throw ValueError(what + " must not be <0, 0, 0>: it gives the warp's direction");
    return o;
}

template <>
struct action<g::warp_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        // The transforms written so far come before this warp (applied
        // after it, world to pattern): they become a step of their own.
        const PatternSlot slot = pattern_slot(st, in.position(), "warp");
        if (!slot.transform.empty()) {
            runtime::pattern::Warp step;
            step.transform = slot.transform;
            slot.pattern.warps.push_back(std::move(step));
            slot.transform = {};
        }
        slot.pattern.warps.push_back(runtime::pattern::Warp{});
    }
};

// ---- turbulence
template <>
struct action<g::warp_turbulence> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        warp_being_written(st, in.position()).turbulence.amount =
            to_vector3(v, "warp's turbulence");
    }
};
template <>
struct action<g::warp_setting> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        const std::string name = st.values.pop_name();
        auto& turbulence = warp_being_written(st, in.position()).turbulence;
        if (name == "octaves")
            turbulence.octaves = to_float(v, "octaves");
        else if (name == "omega")
            turbulence.omega = to_float(v, "omega");
        else
            turbulence.lambda = to_float(v, "lambda");
    }
};

// ---- repeat
template <>
struct action<g::warp_repeat_keyword> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        warp_being_written(st, in.position()).point = runtime::pattern::RepeatWarp{};
    }
};
template <>
struct action<g::warp_repeat_direction> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        const runtime::Vector3Function d = to_vector3(v, "the repeat warp's direction");
        // POV-Ray repeats along the one axis whose component is not zero
        // (a component that moves with clock counts as not zero).
        int axis = -1;
        for (int i = 0; i < 3; ++i) {
            const TimeFunction& c = d.c[static_cast<std::size_t>(i)];
            if (c.is_constant() && c.constant() == 0.0) continue;
            if (axis >= 0)
                throw ValueError(
                    "the repeat warp's direction has more than one non-zero component: it "
                    "repeats along one axis only, as in POV-Ray");
            axis = i;
        }
        if (axis < 0)
            throw ValueError(
                "the repeat warp's direction is zero: it needs one non-zero component, the axis "
                "and width of the repeat, as in POV-Ray");
        auto& repeat = point_warp<runtime::pattern::RepeatWarp>(st, in.position());
        repeat.axis = axis;
        repeat.width = d.c[static_cast<std::size_t>(axis)];
    }
};

// ---- black_hole
template <>
struct action<g::warp_black_hole_keyword> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        warp_being_written(st, in.position()).point = runtime::pattern::BlackHoleWarp{};
    }
};
template <>
struct action<g::warp_black_hole_center> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        point_warp<runtime::pattern::BlackHoleWarp>(st, in.position()).center =
            to_vector3(v, "the black hole's centre");
    }
};
template <>
struct action<g::warp_black_hole_radius> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        const TimeFunction radius = to_float(v, "the black hole's radius");
        if (radius.is_constant() && !(radius.constant() >= 0.0))
            throw ValueError("the black hole's radius must not be negative");
        point_warp<runtime::pattern::BlackHoleWarp>(st, in.position()).radius = radius;
    }
};
template <>
struct action<g::warp_black_hole_inverse> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        point_warp<runtime::pattern::BlackHoleWarp>(st, in.position()).inverse = true;
    }
};

// ---- planar, cylindrical, spherical, toroidal, cubic
template <runtime::pattern::MappingShape Shape>
struct mapping_warp_action {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        runtime::pattern::MappingWarp m;
        m.shape = Shape;
        warp_being_written(st, in.position()).point = m;
    }
};
template <>
struct action<g::warp_planar_keyword>
    : mapping_warp_action<runtime::pattern::MappingShape::Planar> {};
template <>
struct action<g::warp_toroidal_keyword>
    : mapping_warp_action<runtime::pattern::MappingShape::Toroidal> {};
template <>
struct action<g::warp_cubic_keyword> : mapping_warp_action<runtime::pattern::MappingShape::Cubic> {
};
template <>
struct action<g::warp_round_keyword> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        using S = runtime::pattern::MappingShape;
        runtime::pattern::MappingWarp m;
        m.shape = in.string() == "cylindrical" ? S::Cylindrical : S::Spherical;
        warp_being_written(st, in.position()).point = m;
    }
};
template <>
struct action<g::warp_planar_normal> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        point_warp<runtime::pattern::MappingWarp>(st, in.position()).orientation =
            warp_orientation(v, "the planar warp's normal");
    }
};
template <>
struct action<g::warp_planar_distance> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        point_warp<runtime::pattern::MappingWarp>(st, in.position()).distance =
            to_float(v, "the planar warp's distance");
    }
};

// ---- the settings after a warp's keyword
template <>
struct action<g::warp_repeat_option_name> : name_action {};
template <>
struct action<g::warp_black_hole_option_name> : name_action {};
template <>
struct action<g::warp_round_option_name> : name_action {};
template <>
struct action<g::warp_toroidal_option_name> : name_action {};

template <class Name>
struct action<g::warp_option<Name>> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        const std::string name = st.values.pop_name();
        runtime::pattern::Warp& warp = warp_being_written(st, in.position());
        const std::string what = "the warp's " + name;
        if (auto* r = std::get_if<runtime::pattern::RepeatWarp>(&*warp.point)) {
            (name == "offset" ? r->offset : r->flip) = to_vector3(v, what);
        } else if (auto* h = std::get_if<runtime::pattern::BlackHoleWarp>(&*warp.point)) {
            if (name == "strength")
                h->strength = to_float(v, what);
            else if (name == "falloff")
                h->falloff = to_float(v, what);
            else if (name == "type")
                // (POV-Ray's (int) of the number: only type 0 moves points.)
                h->type = static_cast<int>(checked_integer(
                    to_constant(v, what), "the black hole's type", INT_MIN, INT_MAX));
            else
                h->placements.push_back({name == "repeat", to_vector3(v, what)});
        } else {
            auto& m = std::get<runtime::pattern::MappingWarp>(*warp.point);
            if (name == "orientation")
                m.orientation = warp_orientation(v, what);
            else if (name == "dist_exp")
                m.dist_exp = to_float(v, what);
            else
                m.major_radius = to_float(v, what);
        }
    }
};

// A black hole whose repeat is too short for its centre, radius and
// turbulence is widened (Check_BH_Parameters): said once the warp is read,
// as POV-Ray's parser warns, when nothing in it moves.
template <>
struct action<g::warp_block> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        const runtime::pattern::Warp& warp = warp_being_written(st, in.position());
        const auto* h =
            warp.point ? std::get_if<runtime::pattern::BlackHoleWarp>(&*warp.point) : nullptr;
        if (h == nullptr || h->depends_on_time()) return;
        const runtime::pattern::BlackHoleWarp::Placement* written = nullptr;
        for (const auto& p : h->placements)
            if (p.repeat) written = &p;
        if (written == nullptr) return;
        std::vector<double> numbers;
        for (const TimeFunction& n : runtime::pattern::black_hole_numbers(*h))
            numbers.push_back(n.constant());
        const runtime::pattern::BlackHoleAt at =
            runtime::pattern::black_hole_at(*h, numbers.data());
        for (int i = 0; i < 3; ++i) {
            const double asked = written->amount.c[static_cast<std::size_t>(i)].constant();
            if (asked > 0.0 && at.repeat[i] != asked) {
                std::ostringstream message;
                message << "the black hole's repeat along "
                        << "xyz"[i] << " is too small for its "
                        << "centre, radius and turbulence: widened to " << at.repeat[i]
                        << ", as POV-Ray does";
                st.warn(in.position(), message.str());
            }
        }
    }
};

}  // namespace hexant::language
