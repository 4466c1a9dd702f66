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
        ImageMapBuilder b = std::move(std::get<ImageMapBuilder>(st.blocks.top()));
        st.blocks.close();
        // (Read as a height_field's image: the file's values, no gamma.)
        b.gamma.undecoded = true;
        auto map = std::make_shared<runtime::pattern::ImageMap>(std::move(b.map));
        std::map<const image::StoredImage*, std::shared_ptr<const runtime::pattern::ImagePixels>>
            decoded;
        for (const auto& [time, stored] : b.stored) {
            auto& pixels = decoded[stored.get()];
            if (!pixels)
                pixels = std::make_shared<const runtime::pattern::ImagePixels>(
                    image_pixels(*stored, b.gamma, 1.0));
            map->images.push_back({time, pixels});
        }
        auto& normal = st.blocks.edit<runtime::Normal>(in.position(), "bump_map");
        replace_uv_mapping(normal);
        // (The normal's modifiers, turbulence and warps, place the image.)
        runtime::pattern::Pattern fresh;
        fresh.noise_generator = st.scene.global.noise_generator;
        normal.patterned = std::move(fresh);
        normal.normal_map.clear();
        normal.slope_map.clear();
        normal.unsupported_name.clear();
        if (b.bump_size) normal.amount = *b.bump_size;
        normal.bump_map = std::move(map);
    }
};

}  // namespace hexant::language
