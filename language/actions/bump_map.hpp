// bump_map { } in a normal (POV-Ray's Parse_Bump_Map): its file read by
// image_map's actions, its pixels undecoded. Part of the actions
// (language/actions.hpp).
#pragma once

#include "language/actions/materials.hpp"

namespace hexant::language {

template <>
struct action<g::bump_map_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        st.blocks.edit<runtime::Normal>(in.position(), "bump_map");
        st.blocks.open(std::in_place_type<ImageMapBuilder>);
        std::get<ImageMapBuilder>(st.blocks.top()).bump = true;
    }
};
template <>
struct action<g::bump_map_size> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        const TimeFunction v = to_float(st.values.pop(), "bump_size");
        st.blocks.edit<ImageMapBuilder>(in.position(), "bump_size").bump_size = v;
    }
};
template <>
struct action<g::bump_map_block> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        const std::optional<TimeFunction> bump_size =
            std::get<ImageMapBuilder>(st.blocks.top()).bump_size;
        // (Read as a height_field's image: the file's values, no gamma.)
        auto map = finish_image_map(st, in.position(), true);
        st.blocks.close();
        auto& normal = st.blocks.edit<runtime::Normal>(in.position(), "bump_map");
        replace_uv_mapping(normal);
        // (The normal's modifiers, turbulence and warps, place the image.)
        runtime::pattern::Pattern fresh;
        fresh.noise_generator = st.scene.global.noise_generator;
        normal.patterned = std::move(fresh);
        normal.normal_map.clear();
        normal.slope_map.clear();
        normal.unsupported_name.clear();
        if (bump_size) normal.amount = *bump_size;
        normal.bump_map = std::move(map);
    }
};

}  // namespace hexant::language
