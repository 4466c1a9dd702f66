// Maps: pigment, normal and texture maps, and block patterns' lists.
// Part of the actions (language/actions.hpp).
#pragma once

#include "language/actions/warps.hpp"

namespace hexant::language {

// ---- maps of pigments, normals and textures, and block patterns' lists

// A map entry's block closed (a pigment, normal or texture): it and the
// value written before it become an entry of the map of the block around
// it, at most 256 as in POV-Ray.
template <class Record, class Entry>
void close_map_entry(Interpreter& st, const p::position& at, const std::string& map,
                     std::vector<Entry> Record::*entries) {
    const std::string what = "a " + map + " entry";
    auto entry = std::make_shared<Record>(std::move(st.blocks.edit<Record>(at, what.c_str())));
    st.blocks.close();
    const TimeFunction value = to_float(st.values.pop(), what + "'s value");
    auto& outer = st.blocks.edit<Record>(at, what.c_str());
    (outer.*entries).push_back({value, std::move(entry)});
    if ((outer.*entries).size() > 256)
        throw ValueError("a " + map + " has at most 256 entries, as in POV-Ray");
}

// A normal or texture for a block pattern (checker normal { } normal { }):
// its map's entries at 0, 1, 2 (POV-Ray's Parse_Blend_List).
template <class Entry, class Item>
void add_to_block_list(std::vector<Entry>& map, const runtime::pattern::Pattern& pattern, Item item,
                       const char* what) {
    using A = runtime::pattern::Kind::Argument;
    if (pattern.kind == nullptr || pattern.kind->argument != A::Colours)
        throw ValueError(std::string("a ") + what + " inside a " + what +
                         " follows a block pattern (checker, brick, hexagon) as one of its " +
                         what + "s");
    if (map.size() >= static_cast<std::size_t>(pattern.kind->colours))
        throw ValueError(std::string(pattern.kind->name) + " takes at most " +
                         std::to_string(pattern.kind->colours) + " " + what + "s");
    map.push_back({static_cast<double>(map.size()), std::move(item)});
}
// A map's pattern must be one that gives values (POV-Ray refuses the block
// patterns with a map, and average with a slope_map).
inline void check_map_pattern(const runtime::pattern::Pattern& pattern, const char* map) {
    if (pattern.kind && pattern.kind->argument == runtime::pattern::Kind::Argument::Colours)
        throw ValueError(std::string("a ") + map + " cannot go with " +
                         std::string(pattern.kind->name) + ", as in POV-Ray");
    if (pattern.kind && pattern.kind->average && std::string_view(map) == "slope_map")
        throw ValueError("a slope_map cannot go with average, as in POV-Ray");
}

// A map entry written without its value: an average's weight of 1
// (POV-Ray's Parse_Blend_Map: Allow_Float(1.0) for AVERAGE_PATTERN); any
// other map's entry needs its value.
template <class Record>
void default_weight(Interpreter& st, const p::position& at, const char* map) {
    const std::string what = std::string("expected the value of the ") + map + "'s entry";
    const auto& outer = st.blocks.edit<Record>(at, what.c_str());
    if (outer.patterned->kind == nullptr || !outer.patterned->kind->average)
        throw ValueError(what + " (only average's entries may leave it out, weighing 1)");
    st.values.push(Value{TimeFunction(1.0)});
}
template <>
struct action<g::pigment_map_weight> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        default_weight<runtime::Pigment>(st, in.position(), "pigment map");
    }
};
template <>
struct action<g::normal_map_weight> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        default_weight<runtime::Normal>(st, in.position(), "normal map");
    }
};
template <>
struct action<g::texture_map_weight> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        default_weight<runtime::Texture>(st, in.position(), "texture map");
    }
};

template <>
struct action<g::pigment_list_pigment> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        auto entry = std::make_shared<runtime::Pigment>(st.values.pop().as<runtime::Pigment>());
        auto& outer = st.blocks.edit<runtime::Pigment>(in.position(), "a pigment");
        add_to_block_list(outer.pigment_map, outer.patterned,
                          std::shared_ptr<const runtime::Pigment>(std::move(entry)), "pigment");
    }
};
template <>
struct action<g::normal_map_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        auto& normal = st.blocks.edit<runtime::Normal>(in.position(), "normal_map");
        check_map_pattern(normal.patterned, "normal_map");
        normal.normal_map.clear();
    }
};
template <>
struct action<g::normal_map_normal_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        // (From #default's pattern-less normal, as POV-Ray's Parse_Tnormal.)
        st.blocks.open(st.default_normal_start ? *st.default_normal_start : runtime::Normal());
    }
};
template <>
struct action<g::normal_map_entry> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        auto& written = st.blocks.edit<runtime::Normal>(in.position(), "a normal_map entry");
        if (written.patterned->kind == nullptr && written.unsupported_name.empty() &&
            !written.bump_map)
            throw ValueError("a normal_map entry needs a pattern (POV-Ray: no normal type given)");
        check_average(written.patterned, !written.normal_map.empty(), "normal_map");
        close_map_entry(st, in.position(), "normal_map", &runtime::Normal::normal_map);
    }
};
template <>
struct action<g::normal_list_normal> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        auto entry = std::make_shared<runtime::Normal>(st.values.pop().as<runtime::Normal>());
        auto& outer = st.blocks.edit<runtime::Normal>(in.position(), "a normal");
        add_to_block_list(outer.normal_map, outer.patterned,
                          std::shared_ptr<const runtime::Normal>(std::move(entry)), "normal");
    }
};
template <>
struct action<g::slope_map_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        auto& normal = st.blocks.edit<runtime::Normal>(in.position(), "slope_map");
        check_map_pattern(normal.patterned, "slope_map");
        normal.slope_map.clear();
    }
};
template <>
struct action<g::slope_map_entry> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        std::vector<Value> items = st.values.close_frame();
        // [value <height, slope>] (a 2-vector; a bare pair of numbers too).
        runtime::SlopeMapEntry e;
        if (items.size() == 2) {
            e.value = to_float(items[0], "a slope_map entry's value");
            const runtime::Vector3Function hs =
                to_vector3(items[1], "a slope_map entry's <height, slope>");
            e.height = hs.c[0];
            e.slope = hs.c[1];
        } else {
            throw ValueError("a slope_map entry is [value <height, slope>], not " +
                             std::to_string(items.size()) + " values");
        }
        auto& normal = st.blocks.edit<runtime::Normal>(in.position(), "a slope_map entry");
        normal.slope_map.push_back(std::move(e));
        if (normal.slope_map.size() > 256)
            throw ValueError("a slope_map has at most 256 entries, as in POV-Ray");
    }
};

template <>
struct action<g::texture_map_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        auto& texture = st.blocks.edit<runtime::Texture>(in.position(), "texture_map");
        if (texture.patterned->kind == nullptr)
            throw ValueError(
                "a texture_map follows its pattern (texture { PATTERN texture_map { } })");
        check_map_pattern(texture.patterned, "texture_map");
        texture.texture_map.clear();
    }
};
template <>
struct action<g::texture_map_texture_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        // A copy of the #default texture, as POV-Ray's Parse_Texture.
        st.blocks.open(st.scene.default_texture);
    }
};
template <>
struct action<g::texture_map_entry> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        auto& written = st.blocks.edit<runtime::Texture>(in.position(), "a texture_map entry");
        check_patterned_texture(written);
        close_map_entry(st, in.position(), "texture_map", &runtime::Texture::texture_map);
    }
};
template <>
struct action<g::texture_list_texture> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        auto entry = std::make_shared<runtime::Texture>(st.values.pop().as<runtime::Texture>());
        auto& outer = st.blocks.edit<runtime::Texture>(in.position(), "a texture");
        add_to_block_list(outer.texture_map, outer.patterned,
                          std::shared_ptr<const runtime::Texture>(std::move(entry)), "texture");
    }
};

// tiles { A... tile2 B... }: POV-Ray's Parse_Tiles, a texture of the
// checker pattern over two (layered) textures. It keeps its old order: the
// first tile's textures at 1 (where the checker is 1), tile2's at 0.
template <>
struct action<g::tiles_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        auto& texture = st.blocks.edit<runtime::Texture>(in.position(), "tiles");
        // (Not the #default texture: POV-Ray's Parse_Tiles starts afresh.)
        texture = runtime::Texture();
        const runtime::pattern::Kind* checker = runtime::pattern::find_kind("checker");
        if (checker == nullptr) throw std::logic_error("tiles: no checker pattern");
        texture.patterned = runtime::pattern::Pattern::of(*checker);
        texture.patterned.edit().noise_generator = st.scene.global.noise_generator;
    }
};
// A tile's texture, layered over the ones before it in the same tile
// (POV-Ray's Link_Textures: the later on top).
inline void add_tile_texture(Interpreter& st, const p::position& at, std::size_t tile) {
    runtime::Texture written = st.values.pop().as<runtime::Texture>();
    auto& texture = st.blocks.edit<runtime::Texture>(at, "tiles");
    auto& map = texture.texture_map;
    if (map.size() == tile) {
        map.push_back(
            {tile == 0 ? 1.0 : 0.0, std::make_shared<const runtime::Texture>(std::move(written))});
        return;
    }
    map.back().texture =
        std::make_shared<const runtime::Texture>(layered(std::move(written), *map.back().texture));
}
template <>
struct action<g::tiles_texture> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        add_tile_texture(st, in.position(), 0);
    }
};
template <>
struct action<g::tile2_texture> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        add_tile_texture(st, in.position(), 1);
    }
};
template <>
struct action<g::tiles_block> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        // In the map's order of values: tile2's (0), then the first (1).
        auto& map = st.blocks.edit<runtime::Texture>(in.position(), "tiles").texture_map;
        if (map.size() == 2) std::swap(map[0], map[1]);
    }
};

template <>
struct action<g::pigment_map_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        auto& pigment = st.blocks.edit<runtime::Pigment>(in.position(), "pigment_map");
        if (pigment.patterned->kind &&
            pigment.patterned->kind->argument == runtime::pattern::Kind::Argument::Colours)
            throw ValueError(std::string("a pigment_map cannot go with ") +
                             std::string(pigment.patterned->kind->name) + ", as in POV-Ray");
        pigment.pigment_map.clear();
    }
};
template <>
struct action<g::pigment_map_pigment_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        st.blocks.open(std::in_place_type<runtime::Pigment>);
    }
};
template <>
struct action<g::pigment_map_entry> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        const auto& written =
            st.blocks.edit<runtime::Pigment>(in.position(), "a pigment_map entry");
        check_average(written.patterned, !written.pigment_map.empty(), "pigment_map");
        close_map_entry(st, in.position(), "pigment_map", &runtime::Pigment::pigment_map);
    }
};

}  // namespace hexant::language
