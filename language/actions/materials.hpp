// Image maps, colour maps, finishes, interiors, textures and materials.
// Part of the actions (language/actions.hpp).
#pragma once

#include "language/actions/interior.hpp"

namespace hexant::language {

// ---- image_map { } (POV-Ray's Parse_Image, Parse_Image_Map)
// Why hexant refuses an image type word of POV-Ray 3.7's, or null for one it
// reads (a height_field's pot is read there).
inline const char* image_type_refusal(const std::string& type) {
    if (type == "sys")
        return "sys images: POV-Ray 3.7 on Unix defines no system format ('This platform has "
               "not defined a SYS file type'); name the file's format (png, tga, ...)";
    if (type == "iff")
        return "iff images (Amiga ILBM) are not read: POV-Ray 3.7's reader fails on every file "
               "('Unexpected EOF while reading IFF file', after the last chunk), so no scene "
               "renders with one there either; convert the file to png";
    return nullptr;
}
template <>
struct action<g::image_map_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        st.blocks.edit<runtime::Pigment>(in.position(), "image_map");
        st.blocks.open(std::in_place_type<ImageMapBuilder>);
    }
};
template <>
struct action<g::image_file_type> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        std::string type = in.string();
        while (!type.empty() && std::isspace(static_cast<unsigned char>(type.back())))
            type.pop_back();
        // The file's own bytes say its format; the word is kept for Targa,
        // which has no magic bytes.
        if (const char* refusal = image_type_refusal(type)) throw UnsupportedError(refusal);
        st.blocks.edit<ImageMapBuilder>(in.position(), type.c_str()).type_word = type;
    }
};
template <>
struct action<g::image_map_file> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        auto& b = st.blocks.edit<ImageMapBuilder>(in.position(), "image_map's file");
        const auto read = [&](const std::string& name) {
            const std::filesystem::path path =
                st.resolve_include(name, in.position(), "image file");
            try {
                return std::make_shared<const image::StoredImage>(
                    image::read_stored_image(path, st.max_image_pixels(), b.type_word));
            } catch (const image::ImageTooLarge& e) {
                throw ValueError(std::string("image_map: ") + e.what() +
                                 "; --max-pixels N raises it");
            } catch (const std::runtime_error& e) {
                throw ValueError(std::string("image_map: ") + e.what());
            }
        };
        const runtime::Interval always(-std::numeric_limits<double>::infinity(),
                                       std::numeric_limits<double>::infinity());
        if (v.is<std::string>()) {
            b.map.file = v.as<std::string>();
            b.stored.push_back({always, read(b.map.file)});
        } else if (v.is<TimedString>()) {
            // An image sequence: each file read once, each piece of time
            // showing its own (the clock named where one fails).
            const TimedString& names = v.as<TimedString>();
            std::map<std::string, std::shared_ptr<const image::StoredImage>> files;
            for (const auto& piece : names.pieces) {
                auto& file = files[piece.text];
                if (!file) {
                    try {
                        file = read(piece.text);
                    } catch (const ValueError& e) {
                        throw ValueError(std::string(e.what()) + " [clock " +
                                         std::to_string(piece.time.lo) + " to " +
                                         std::to_string(piece.time.hi) + "]");
                    }
                }
                b.stored.push_back({piece.time, file});
            }
            b.map.file = names.describe();
        } else {
            throw ValueError("image_map's file is a string, not a " + type_name(v));
        }
    }
};
template <>
struct action<g::image_map_gamma_srgb> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        st.blocks.edit<ImageMapBuilder>(in.position(), "gamma").gamma_srgb_next = true;
    }
};
template <>
struct action<g::image_map_gamma> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        auto& b = st.blocks.edit<ImageMapBuilder>(in.position(), "gamma");
        if (b.gamma_srgb_next) {
            b.gamma = ImageGamma{std::nullopt, true};
            b.gamma_srgb_next = false;
            return;
        }
        const double g = to_constant(st.values.pop(), "gamma");
        if (!(g > 0.0) || !std::isfinite(g))
            throw ValueError("an image's gamma must be positive, as in POV-Ray");
        b.gamma = ImageGamma{g, false};
    }
};
template <>
struct action<g::image_map_setting> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        const std::string name = st.values.pop_name();
        auto& b = st.blocks.edit<ImageMapBuilder>(in.position(), name.c_str());
        using M = runtime::pattern::ImageMap;
        if (name == "map_type") {
            // (POV-Ray takes the integer part.)
            const double t = std::trunc(to_constant(v, "map_type"));
            if (t != 0.0 && t != 1.0 && t != 2.0 && t != 5.0)
                throw ValueError(
                    "map_type is 0 (planar), 1 (spherical), 2 (cylindrical) or 5 (torus), as in "
                    "POV-Ray");
            b.map.map_type = static_cast<M::MapType>(static_cast<int>(t));
        } else if (name == "interpolate") {
            const double t = std::trunc(to_constant(v, "interpolate"));
            if (t != 2.0 && t != 3.0 && t != 4.0)
                throw ValueError(
                    "interpolate is 2 (bilinear), 3 (bicubic) or 4 (normalized distance), as in "
                    "POV-Ray");
            b.map.interpolate = static_cast<M::Interpolate>(static_cast<int>(t));
        } else if (name == "premultiplied") {
            // (PNG's alpha is not premultiplied; OpenEXR's is read as it is.)
            if (to_constant(v, "premultiplied") != 0.0)
                throw UnsupportedError(
                    "premultiplied alpha in an image_map is not supported by hexant");
        } else {
            const runtime::Vector3Function uv = to_vector3(v, name);
            const double u = to_constant(Value{uv.c[0]}, name),
                         w = to_constant(Value{uv.c[1]}, name);
            if (name == "repeat") {
                if (!(u > 0.0) || !(w > 0.0))
                    throw ValueError("an image_map's repeat must be positive, as in POV-Ray");
                b.map.repeat_u = u;
                b.map.repeat_v = w;
            } else {
                b.map.offset_u = u;
                b.map.offset_v = w;
            }
        }
    }
};
template <>
struct action<g::image_map_flag> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        std::string flag = in.string();
        while (!flag.empty() && std::isspace(static_cast<unsigned char>(flag.back())))
            flag.pop_back();
        auto& b = st.blocks.edit<ImageMapBuilder>(in.position(), flag.c_str());
        if (flag == "once")
            b.map.once = true;
        else if (b.bump)
            b.map.use_index = flag == "use_index";
        else if (flag == "use_index")
            throw UnsupportedError(
                "use_index in an image_map is not supported by hexant (it reads colours)");
    }
};
template <>
struct action<g::image_map_all> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        st.blocks.edit<ImageMapBuilder>(in.position(), "all").all_next = true;
    }
};
template <>
struct action<g::image_map_filter> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        std::vector<Value> args = st.values.close_frame();
        const std::string name = st.values.pop_name();
        auto& b = st.blocks.edit<ImageMapBuilder>(in.position(), name.c_str());
        const bool all = b.all_next;
        b.all_next = false;
        const bool filter = name == "filter";
        if (all) {
            if (args.size() != 1) throw ValueError(name + " all takes one amount, as in POV-Ray");
            // (Every entry's, the ones set before included.)
            (filter ? b.map.filter_all : b.map.transmit_all) = to_float(args[0], name + " all");
            if (!filter) b.map.transmit_all_written = true;
            for (auto& entry : b.map.palette_entries)
                (filter ? entry.has_filter : entry.has_transmit) = false;
            return;
        }
        if (args.size() != 2)
            throw ValueError(name + " takes a palette entry and an amount (" + name +
                             " N, AMOUNT) or all and an amount, as in POV-Ray");
        // POV-Ray's Parse_Image_Map: the entry (int)(N + 0.01) of a palette
        // image, in its palette.
        const double n = to_constant(args[0], name + "'s palette entry");
        const double entry = std::isfinite(n) ? std::trunc(n + 0.01) : -1.0;
        char written[32];
        std::snprintf(written, sizeof written, "%g", n);
        for (const auto& [time, stored] : b.stored) {
            if (stored->source != image::StoredImage::Source::Palette)
                throw ValueError(name + " N, AMOUNT is only for a palette image, as in POV-Ray; '" +
                                 b.map.file + "' has none (" + name + " all AMOUNT is for any)");
            if (entry < 0.0 || entry >= static_cast<double>(stored->palette.size()))
                throw ValueError(name + "'s palette entry " + written + " is out of range: '" +
                                 b.map.file + "' has " + std::to_string(stored->palette.size()) +
                                 " entries");
        }
        const TimeFunction amount = to_float(args[1], name + " of a palette entry");
        if (!amount.is_constant())
            throw UnsupportedError(name +
                                   " of one palette entry that moves with clock is not "
                                   "supported by hexant; " +
                                   name + " all AMOUNT may move");
        const auto k = static_cast<std::size_t>(entry);
        if (b.map.palette_entries.size() <= k) b.map.palette_entries.resize(k + 1);
        auto& own = b.map.palette_entries[k];
        // (POV-Ray keeps a palette's filter and transmit in single precision.)
        (filter ? own.filter : own.transmit) = static_cast<float>(amount.constant());
        (filter ? own.has_filter : own.has_transmit) = true;
    }
};
// The image map of an image_map { }, material_map { } or bump_map { }
// just read, from the builder on top of the block stack, each distinct file
// decoded once. `undecoded`: the file's values as they are unless the
// scene gave a gamma (POV-Ray's Parse_Image without GammaCorrect: a
// material_map's, a bump_map's); else decoded into the working space.
inline std::shared_ptr<runtime::pattern::ImageMap> finish_image_map(Interpreter& st,
                                                                    const p::position& at,
                                                                    bool undecoded) {
    ImageMapBuilder& b = std::get<ImageMapBuilder>(st.blocks.top());
    if (undecoded) {
        b.gamma.undecoded = true;
    } else {
        st.image_maps_read.push_back(at);
        // (POV-Ray's gamma mode as it stands here: assumed_gamma set under
        // a #version below 3.7.)
        b.gamma.legacy_default = st.assumed_gamma_set && (st.version_set ? st.version : 3.62) < 3.7;
    }
    auto map = std::make_shared<runtime::pattern::ImageMap>(std::move(b.map));
    std::map<const image::StoredImage*, std::shared_ptr<const runtime::pattern::ImagePixels>>
        decoded;
    for (const auto& [time, stored] : b.stored) {
        auto& pixels = decoded[stored.get()];
        if (!pixels)
            pixels = std::make_shared<const runtime::pattern::ImagePixels>(
                image_pixels(*stored, b.gamma, undecoded ? 1.0 : st.scene.global.assumed_gamma));
        map->images.push_back({time, pixels});
    }
    return map;
}

template <>
struct action<g::image_map_block> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        auto map = finish_image_map(st, in.position(), false);
        st.blocks.close();
        auto& pigment = st.blocks.edit<runtime::Pigment>(in.position(), "image_map");
        replace_uv_mapping(pigment);
        // (The pigment's modifiers, turbulence and warps, place the image.)
        pigment.pattern = runtime::Pigment::Pattern::Image;
        pigment.patterned.edit().kind = nullptr;
        pigment.colour_map = {};
        pigment.pigment_map.clear();
        pigment.image_map = std::move(map);
    }
};

// red, green, blue, filter or transmit A in a pigment: the component of its
// plain colour (POV-Ray's Parse_Colour, which reads on after a colour).
template <>
struct action<g::pigment_component> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        const TimeFunction v = to_float(st.values.pop(), "a colour component");
        const std::string name = st.values.pop_name();
        auto& pigment = st.blocks.edit<runtime::Pigment>(in.position(), name.c_str());
        if (pigment.pattern != runtime::Pigment::Pattern::Solid || pigment.colours.size() != 1)
            throw ValueError("'" + name +
                             "' sets a component of a plain colour; this pigment has a pattern");
        pigment.colours[0].c[colour_component_index(name)] = v;
    }
};
template <>
struct action<g::colour_map_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        st.blocks.open(std::in_place_type<runtime::ColourMap>);
    }
};
template <>
struct action<g::colour_map_base> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        if (!v.is<runtime::ColourMap>())
            throw ValueError("color_map { } starts with a color_map, not a " + type_name(v));
        st.blocks.edit<runtime::ColourMap>(in.position(), "a color_map") =
            v.as<runtime::ColourMap>();
    }
};
template <>
struct action<g::colour_map_entry> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        std::vector<Value> items = st.values.close_frame();
        auto& map = st.blocks.edit<runtime::ColourMap>(in.position(), "a color_map entry");
        // [value colour], or POV-Ray's older [value1, value2 colour1 colour2].
        if (items.size() == 2) {
            map.entries.push_back({to_float(items[0], "a color_map entry's value"),
                                   to_colour(items[1], "a color_map entry's colour")});
        } else if (items.size() == 4) {
            map.entries.push_back({to_float(items[0], "a color_map entry's first value"),
                                   to_colour(items[2], "a color_map entry's first colour")});
            map.entries.push_back({to_float(items[1], "a color_map entry's second value"),
                                   to_colour(items[3], "a color_map entry's second colour")});
        } else {
            throw ValueError(
                "a color_map entry is [value colour] (or [value1, value2 colour1 colour2]), not " +
                std::to_string(items.size()) + " values");
        }
        if (map.entries.size() > 256)
            throw ValueError("a color_map has at most 256 entries, as in POV-Ray");
    }
};
template <>
struct action<g::colour_map_block> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        auto& map = st.blocks.edit<runtime::ColourMap>(in.position(), "a color_map");
        if (map.entries.empty()) throw ValueError("a color_map needs at least one entry");
        Value v{std::move(map)};
        st.blocks.close();
        st.values.push(std::move(v));
    }
};
template <>
struct action<g::pigment_colour_map> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        auto& pigment = st.blocks.edit<runtime::Pigment>(in.position(), "color_map");
        if (pigment.patterned->kind &&
            pigment.patterned->kind->argument == runtime::pattern::Kind::Argument::Colours)
            throw ValueError(std::string("a color_map cannot go with ") +
                             std::string(pigment.patterned->kind->name) +
                             " (its colours follow its name), as in POV-Ray");
        if (pigment.patterned->kind && pigment.patterned->kind->average)
            throw ValueError(
                "a color_map cannot go with average (it averages a pigment_map), "
                "as in POV-Ray");
        pigment.colour_map = v.as<runtime::ColourMap>();
    }
};
template <>
struct action<g::unsupported_pattern> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        if (!st.blocks.empty() && std::holds_alternative<runtime::Normal>(st.blocks.top())) {
            auto& normal = st.blocks.edit<runtime::Normal>(in.position(), "a pattern");
            normal.unsupported_name = st.values.pop_name();
            normal.unsupported_place = {in.position().source, in.position().line,
                                        in.position().column};
            return;
        }
        auto& pigment = st.blocks.edit<runtime::Pigment>(in.position(), "a pattern");
        pigment.pattern = runtime::Pigment::Pattern::Unsupported;
        pigment.unsupported_name = st.values.pop_name();
        pigment.unsupported_place = {in.position().source, in.position().line,
                                     in.position().column};
    }
};
// (The same in a pigment_map's entry.)
template <>
struct action<g::map_entry_unsupported_pattern> : action<g::unsupported_pattern> {};
template <>
struct action<g::pigment_block> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        auto& pigment = std::get<runtime::Pigment>(st.blocks.top());
        close_pigment(pigment);
        Value v{pigment};
        st.blocks.close();
        st.values.push(std::move(v));
    }
};

template <>
struct action<g::finish_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        // Into the finish it modifies, as POV-Ray's Parse_Finish: a texture's
        // (texture { T finish { phong 1 } } keeps T's other settings), or the
        // #default one's.
        refuse_patterned_edit(st, "finish");
        const runtime::Texture* texture = texture_being_written(st);
        st.blocks.open(texture ? texture->finish.get() : runtime::Finish());
    }
};
template <>
struct action<g::finish_base> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        if (!v.is<runtime::Finish>())
            throw ValueError("finish { } starts with a finish, not a " + type_name(v));
        st.blocks.edit<runtime::Finish>(in.position(), "a finish") = v.as<runtime::Finish>();
    }
};
template <>
struct action<g::finish_setting> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        std::vector<Value> given = st.values.close_frame();
        const std::string name = st.values.pop_name();
        auto& f = st.blocks.edit<runtime::Finish>(in.position(), name.c_str());
        if (given.size() > 1) {
            if (name != "diffuse") throw ValueError("a finish's " + name + " takes one value");
            f.diffuse_back = to_float(given[1], "diffuse's second value");
        }
        Value v = std::move(given.at(0));
        if (name == "ambient" || name == "emission") {
            // A colour (ambient rgb <..>) or a float, grey (POV-Ray 3.7's
            // Parse_Finish reads both as colours).
            std::array<TimeFunction, 3> amount;
            if (v.is<Vector>()) {
                const auto c = to_colour(v, name);
                amount = {c.c[0], c.c[1], c.c[2]};
            } else {
                const TimeFunction x = to_float(v, name);
                amount = {x, x, x};
            }
            (name == "ambient" ? f.ambient : f.emission) = amount;
            return;
        }
        TimeFunction x;
        if (v.is<Vector>()) {
            // A colour amount where POV-Ray reads a float: hexant keeps its
            // mean.
            const auto c = to_colour(v, name);
            x = (c.c[0] + c.c[1] + c.c[2]) / 3.0;
            const auto constant = [&](int i) { return c.c[i].is_constant(); };
            const bool grey = constant(0) && constant(1) && constant(2) &&
                              c.c[0].constant() == c.c[1].constant() &&
                              c.c[1].constant() == c.c[2].constant();
            if (!grey)
                f.unrendered.push_back(
                    {{in.position().source, in.position().line, in.position().column},
                     name + " is a colour here; hexant renders the mean of its red, green and "
                            "blue, not the colour"});
        } else {
            x = to_float(v, name);
        }
        if (name == "diffuse")
            f.diffuse = x;
        else if (name == "brilliance")
            f.brilliance = x;
        else if (name == "phong")
            f.phong = x;
        else if (name == "phong_size")
            f.phong_size = x;
        else if (name == "specular")
            f.specular = x;
        else if (name == "roughness")
            f.roughness = x;
        else if (name == "crand")
            f.crand = x;
    }
};
// reflection V or reflection { MIN ...}: the minimum; the maximum the
// same until one is written (POV-Ray's Parse_Finish). The old syntax, V
// alone, also puts the falloff back to 1.
// (A float is grey; a colour's filter and transmit do not count.)
inline runtime::ColourFunction reflection_colour(const Value& v, const std::string& what) {
    if (v.is<TimeFunction>()) {
        const TimeFunction x = v.as<TimeFunction>();
        return runtime::ColourFunction{{x, x, x, 0.0, 0.0}};
    }
    runtime::ColourFunction c = to_colour(v, what);
    c.c[3] = c.c[4] = 0.0;
    return c;
}
inline void set_reflection(runtime::Finish& f, const Value& v) {
    f.reflection = reflection_colour(v, "reflection");
    f.reflection_max.reset();
}
template <>
struct action<g::reflection_value> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        set_reflection(st.blocks.edit<runtime::Finish>(in.position(), "reflection"), v);
    }
};
template <>
struct action<g::reflection_plain_value> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        auto& f = st.blocks.edit<runtime::Finish>(in.position(), "reflection");
        set_reflection(f, v);
        f.reflection_falloff = 1.0;
    }
};
template <>
struct action<g::reflection_maximum_value> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        st.blocks.edit<runtime::Finish>(in.position(), "reflection").reflection_max =
            reflection_colour(v, "reflection's maximum");
    }
};
template <>
struct action<g::reflection_number_name> : name_action {};
template <>
struct action<g::reflection_number_value> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        const TimeFunction x = to_float(st.values.pop(), "the reflection's value");
        const std::string name = st.values.pop_name();
        auto& f = st.blocks.edit<runtime::Finish>(in.position(), name.c_str());
        if (name == "exponent") {
            // (POV-Ray keeps 1 / exponent: 0 would make it infinite.)
            if (x.is_constant() && x.constant() == 0.0)
                throw ValueError("the reflection's exponent must not be 0");
            f.reflection_exponent = x;
        } else {
            f.reflection_falloff = x;
        }
    }
};
template <>
struct action<g::reflection_fresnel> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        std::vector<Value> given = st.values.close_frame();
        // POV-Ray's (int) Allow_Float(1.0) != 0.
        const double on = given.empty() ? 1.0 : to_constant(given[0], "fresnel");
        st.blocks.edit<runtime::Finish>(in.position(), "fresnel").reflection_fresnel =
            std::trunc(on) != 0.0;
    }
};
template <>
struct action<g::irid_amount> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        st.blocks.edit<runtime::Finish>(in.position(), "irid").irid =
            to_float(st.values.pop(), "irid");
    }
};
template <>
struct action<g::irid_setting_name> : name_action {};
template <>
struct action<g::irid_setting_value> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        const std::string name = st.values.pop_name();
        auto& f = st.blocks.edit<runtime::Finish>(in.position(), name.c_str());
        if (name == "thickness")
            f.irid_thickness = to_float(v, "irid's thickness");
        else  // (POV-Ray reads a vector and keeps its x.)
            f.irid_turbulence = v.is<Vector>() ? to_vector(v, "irid's turbulence").c[0]
                                               : to_float(v, "irid's turbulence");
    }
};
template <>
struct action<g::finish_conserve_energy> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        st.blocks.edit<runtime::Finish>(in.position(), "conserve_energy").conserve_energy = true;
    }
};
// metallic [AMOUNT] in a finish, or in its reflection { }: 1 when no
// amount is written (POV-Ray's Allow_Float(1.0)).
inline TimeFunction metallic_amount(Interpreter& st) {
    std::vector<Value> given = st.values.close_frame();
    return given.empty() ? TimeFunction(1.0) : to_float(given[0], "metallic");
}
template <>
struct action<g::finish_metallic> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        const TimeFunction amount = metallic_amount(st);
        st.blocks.edit<runtime::Finish>(in.position(), "metallic").metallic = amount;
    }
};
template <>
struct action<g::reflection_metallic> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        const TimeFunction amount = metallic_amount(st);
        st.blocks.edit<runtime::Finish>(in.position(), "metallic").reflection_metallic = amount;
    }
};
// A finish's own fresnel (POV-Ray 3.8's), subsurface { }: kept
// with the finish, warned where it is used.
template <>
struct action<g::finish_flag> : unrendered_action<runtime::Finish> {};
template <>
struct action<g::finish_ignored_block> : unrendered_action<runtime::Finish> {};
template <>
struct action<g::ignored_value> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        st.values.pop();
    }
};
template <>
struct action<g::finish_block> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        Value v{std::get<runtime::Finish>(st.blocks.top())};
        st.blocks.close();
        st.values.push(std::move(v));
    }
};

// uv_mapping: the pigment, normal or texture being written reads (u, v, 0).
template <>
struct action<g::uv_mapping> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        if (st.blocks.empty())
            throw ValueError("uv_mapping belongs in a pigment, a normal or a texture");
        auto& b = st.blocks.top();
        // (What follows is a pigment or normal of its own, POV-Ray's
        // Parse_Item_Into_Blend_List from the default: nothing written
        // before in this block, or in one it modifies, carries over.)
        if (auto* pigment = std::get_if<runtime::Pigment>(&b)) {
            *pigment = runtime::Pigment();
            pigment->uv_mapping = runtime::UvMapping::Open;
        } else if (auto* normal = std::get_if<runtime::Normal>(&b)) {
            *normal = runtime::Normal();
            normal->uv_mapping = runtime::UvMapping::Open;
        } else if (auto* texture = std::get_if<runtime::Texture>(&b))
            texture->uv_mapping = runtime::UvMapping::Open;
        else
            throw ValueError("uv_mapping belongs in a pigment, a normal or a texture");
        (void)in;
    }
};
template <>
struct action<g::texture_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        // A copy of the #default texture, as POV-Ray's Parse_Texture.
        st.blocks.open(st.scene.default_texture);
    }
};
template <>
struct action<g::texture_base> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        auto& t = st.blocks.edit<runtime::Texture>(in.position(), "a texture");
        if (v.is<runtime::Texture>())
            t = v.as<runtime::Texture>();
        else if (v.is<runtime::Pigment>())
            t.pigment = v.as<runtime::Pigment>();
        else
            throw ValueError("texture { } starts with a texture, not a " + type_name(v));
    }
};
template <>
struct action<g::texture_pigment> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        st.blocks.edit<runtime::Texture>(in.position(), "pigment").pigment =
            v.as<runtime::Pigment>();
    }
};
template <>
struct action<g::texture_finish> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        st.blocks.edit<runtime::Texture>(in.position(), "finish").finish =
            st.finishes.share(std::move(v.as<runtime::Finish>()));
    }
};
template <>
struct action<g::texture_block> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        check_patterned_texture(std::get<runtime::Texture>(st.blocks.top()));
        close_uv_mapping(std::get<runtime::Texture>(st.blocks.top()).uv_mapping);
        Value v{std::get<runtime::Texture>(st.blocks.top())};
        st.blocks.close();
        st.values.push(std::move(v));
    }
};
// material_map { }: a texture of the material_map pattern over the
// textures written, at 0, 1, ... in its map (POV-Ray's Parse_Material_Map
// starts afresh, not from the #default texture).
template <>
struct action<g::material_map_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        auto& texture = st.blocks.edit<runtime::Texture>(in.position(), "material_map");
        texture = runtime::Texture();
        const runtime::pattern::Kind* kind = runtime::pattern::find_kind("material_map");
        if (kind == nullptr) throw std::logic_error("material_map: no such pattern kind");
        texture.patterned = runtime::pattern::Pattern::of(*kind);
        st.blocks.open(std::in_place_type<ImageMapBuilder>);
    }
};
template <>
struct action<g::material_map_texture> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        auto written =
            std::make_shared<const runtime::Texture>(st.values.pop().as<runtime::Texture>());
        std::get<ImageMapBuilder>(st.blocks.top()).materials.push_back(std::move(written));
    }
};
template <>
struct action<g::material_map_block> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        auto materials = std::move(std::get<ImageMapBuilder>(st.blocks.top()).materials);
        // (Read without gamma correction, as POV-Ray's Parse_Material_Map:
        // a colour image's red picks by the file's value.)
        auto map = finish_image_map(st, in.position(), true);
        st.blocks.close();
        auto& texture = st.blocks.edit<runtime::Texture>(in.position(), "material_map");
        texture.patterned.edit().image = std::move(map);
        texture.patterned.edit().number[0] = double(materials.size());
        texture.texture_map.clear();
        for (std::size_t i = 0; i < materials.size(); ++i)
            texture.texture_map.push_back({double(i), std::move(materials[i])});
    }
};

// interior_texture { }: read as a texture { } is.
template <>
struct action<g::interior_texture_open> : action<g::texture_open> {};
template <>
struct action<g::interior_texture_block> : action<g::texture_block> {};
template <>
struct action<g::texture_layer> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        // texture { A } texture { B }: B on top of A.
        (void)in;
        runtime::Texture top = st.values.pop().as<runtime::Texture>();
        if (st.values.top().is<Unevaluated>()) return;
        st.values.top() =
            Value{layered(std::move(top), std::move(st.values.top().as<runtime::Texture>()))};
    }
};
template <>
struct action<g::material_value> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        Value v{std::get<MaterialBuilder>(st.blocks.top())};
        st.blocks.close();
        st.values.push(std::move(v));
    }
};
template <>
struct action<g::material_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        st.blocks.open(std::in_place_type<MaterialBuilder>);
    }
};
template <>
struct action<g::material_base> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        // material { M ... }: a copy of the declared material, then its changes.
        Value v = st.values.pop();
        if (!v.is<Material>())
            throw ValueError("material { } starts with a material, not a " + type_name(v));
        st.blocks.edit<MaterialBuilder>(in.position(), "material") = v.as<Material>();
    }
};
template <>
struct action<g::material_texture> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        auto& material = st.blocks.edit<MaterialBuilder>(in.position(), "texture");
        auto texture = v.as<runtime::Texture>();
        material.texture = material.texture
                               ? layered(std::move(texture), std::move(*material.texture))
                               : std::move(texture);
    }
};
template <>
struct action<g::material_interior> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        st.blocks.edit<MaterialBuilder>(in.position(), "interior").interior =
            v.as<runtime::Interior>();
    }
};

}  // namespace hexant::language
