// Patterns: pigments, normals and textures with a pattern, its settings and waves.
// Part of the actions (language/actions.hpp).
#pragma once

#include "language/actions/transformations.hpp"
#include "language/object_extent.hpp"
#include "language/scene_queries.hpp"
#include "runtime/objects/object_error.hpp"
#include "runtime/texture/pattern/density_file.hpp"

namespace hexant::language {

// ------------------------------------------------------------ textures

// The pigment or normal an object, a texture or the camera already has:
// a second pigment { } there modifies it (POV-Ray parses into the one it
// has), it does not start over.
//
// Where POV-Ray starts from a copy of the #default texture instead (an
// object without a texture yet, a pigment, normal or finish declared or
// given to #default: Parse_Object_Mods, Parse_Declare and Parse_Default in
// its parser.cpp), the start is the scene's default texture. Elsewhere
// (sky_sphere, rainbow: its Create_Pigment) there is none.
inline const runtime::Texture* texture_being_written(const Interpreter& st) {
    if (st.blocks.empty()) return &st.scene.default_texture;
    if (const auto* t = std::get_if<runtime::Texture>(&st.blocks.top())) return t;
    if (const auto* o = std::get_if<runtime::ObjectRecord>(&st.blocks.top()))
        return o->texture ? &*o->texture : &st.scene.default_texture;
    return nullptr;
}

// A texture block that has become patterned (a declared texture_map,
// material_map, tiles or block pattern's texture, or one written before
// it) takes no pigment, normal or finish of its own: POV-Ray's
// Parse_Texture reads them only for a plain texture ("No matching } in
// 'texture', finish found"). Said here, where hexant would drop it.
inline void refuse_patterned_edit(const Interpreter& st, const char* what) {
    if (st.blocks.empty()) return;
    const auto* texture = std::get_if<runtime::Texture>(&st.blocks.top());
    if (texture != nullptr && texture->is_patterned())
        throw ValueError(std::string("a patterned texture (texture_map, material_map, tiles, a "
                                     "block pattern's textures) takes no ") +
                         what + " of its own, as in POV-Ray: give it to each of its textures");
}

// A pigment { } or normal { } that edits the texture being written
// continues its pigment or normal after the transforms the texture has had
// so far: POV-Ray keeps no transform of a plain texture's own but moves its
// pigment and normal (Transform_Textures), so `texture { T rotate x
// pigment { rotate y } }` turns T's pigment by x, then y. hexant keeps
// them on the texture; they are folded into its pigment and normal here,
// before either is edited, so that the edit comes after them.
inline void fold_texture_transform(Interpreter& st) {
    const runtime::Texture* written = texture_being_written(st);
    if (written == nullptr || written == &st.scene.default_texture) return;
    // (The texture's own block, or an object's texture: not const.)
    auto& texture = const_cast<runtime::Texture&>(*written);
    if (texture.transform.empty() || texture.is_patterned() ||
        texture.uv_mapping != runtime::UvMapping::Off)
        return;
    texture.pigment.transform.append(texture.transform);
    if (texture.normal) texture.normal->transform.append(texture.transform);
    texture.transform = runtime::Transform();
}

template <>
struct action<g::pigment_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        refuse_patterned_edit(st, "pigment");
        fold_texture_transform(st);
        const runtime::Texture* texture = texture_being_written(st);
        runtime::Pigment start = texture ? texture->pigment : runtime::Pigment();
        st.blocks.open(std::move(start));
    }
};
template <>
struct action<g::pigment_base> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        auto& pigment = st.blocks.edit<runtime::Pigment>(in.position(), "a pigment");
        if (v.is<runtime::Pigment>()) {
            pigment = v.as<runtime::Pigment>();
        } else {
            pigment = runtime::Pigment();
            pigment.colours = {to_colour(v, "a pigment")};
        }
    }
};
template <>
struct action<g::pigment_late_colour> : action<g::pigment_base> {};
// ---- patterns (runtime/texture/pattern/pattern.hpp), in a pigment or a normal

// The pattern being written: a pigment's, a normal's or a texture's.
struct PatternSlot {
    runtime::pattern::Pattern& pattern;
    runtime::Transform& transform;
    runtime::Pigment* pigment = nullptr;  // (one of the three)
    runtime::Normal* normal = nullptr;
    runtime::Texture* texture = nullptr;
};
// (`starts` for the pattern's name itself: in a texture, a modifier comes
// after it.)
// A uv-mapped block, once written, takes no transforms from outside it.
inline void close_uv_mapping(runtime::UvMapping& m) {
    if (m == runtime::UvMapping::Open) m = runtime::UvMapping::Closed;
}
// A new pattern written over a uv-mapped pigment or normal of an earlier
// block (a second pigment { } on the object): POV-Ray's Parse_Pattern
// replaces the uv map, and the transforms that lived inside it go with it.
template <class Record>
void replace_uv_mapping(Record& r) {
    if (r.uv_mapping != runtime::UvMapping::Closed) return;
    r.uv_mapping = runtime::UvMapping::Off;
    r.transform = {};
}

inline PatternSlot pattern_slot(Interpreter& st, const p::position& at, const char* what,
                                bool starts = false) {
    if (!st.blocks.empty()) {
        if (auto* n = std::get_if<runtime::Normal>(&st.blocks.top()))
            return {n->patterned.edit(), n->transform, nullptr, n};
        if (auto* t = std::get_if<runtime::Texture>(&st.blocks.top())) {
            if (t->patterned->kind == nullptr && !starts)
                throw ValueError(
                    std::string(what) +
                    " in a texture follows a pattern (texture { PATTERN texture_map { } })");
            return {t->patterned.edit(), t->transform, nullptr, nullptr, t};
        }
    }
    auto& pigment = st.blocks.edit<runtime::Pigment>(at, what);
    return {pigment.patterned.edit(), pigment.transform, &pigment};
}

// average has no value of its own: it needs its map's entries to average
// (POV-Ray's Parse_Pattern: "Average must have map").
inline void check_average(const runtime::pattern::Pattern& pattern, bool has_map, const char* map) {
    if (pattern.kind && pattern.kind->average && !has_map)
        throw ValueError(std::string("average needs a ") + map +
                         " of the entries it averages, as in POV-Ray");
}

// The pattern `name` starts in the block being written (a pigment's, a
// normal's or a texture's), with its defaults: what follows its name sets
// its arguments.
inline PatternSlot start_pattern(Interpreter& st, const p::position& at, const std::string& name) {
    const PatternSlot slot = pattern_slot(st, at, "a pattern", true);
    const runtime::pattern::Kind* kind = runtime::pattern::find_kind(name);
    if (kind == nullptr) throw ValueError("no pattern " + name);
    if (slot.pigment) replace_uv_mapping(*slot.pigment);
    if (slot.normal) {
        replace_uv_mapping(*slot.normal);
        slot.normal->bump_map = nullptr;
    }
    slot.pattern = runtime::pattern::Pattern::of(*kind);
    // (The scene's noise generator, global_settings { noise_generator }.)
    slot.pattern.noise_generator = st.scene.global.noise_generator;
    slot.pattern.number_of_waves = st.scene.global.number_of_waves;
    ++st.patterns_written;
    if (slot.pigment) {
        slot.pigment->pattern = runtime::Pigment::Pattern::Patterned;
        slot.pigment->colour_map = {};
    }
    if (slot.texture) {
        // (POV-Ray: a texture is plain or patterned; a pattern after
        // its layers or in a declared plain one starts it over.)
        if (!slot.texture->below.empty())
            throw ValueError("a layered texture cannot take a pattern (" + name + ")");
        slot.texture->texture_map.clear();
    }
    return slot;
}

// A pigment's block written (pigment { }, pigment_pattern { }): a block
// pattern given fewer pigments than it takes has its default colours for
// the rest (POV-Ray's Parse_Blend_List); an average has its map.
inline void close_pigment(runtime::Pigment& pigment) {
    const auto* kind = pigment.patterned->kind;
    if (kind && kind->argument == runtime::pattern::Kind::Argument::Colours &&
        !pigment.pigment_map.empty())
        for (std::size_t i = pigment.pigment_map.size(); i < pigment.colour_map.entries.size();
             ++i) {
            auto solid = std::make_shared<runtime::Pigment>();
            solid->colours = {pigment.colour_map.entries[i].colour};
            pigment.pigment_map.push_back({static_cast<double>(i), std::move(solid)});
        }
    if (pigment.pattern == runtime::Pigment::Pattern::Patterned)
        check_average(pigment.patterned, !pigment.pigment_map.empty(), "pigment_map");
    close_uv_mapping(pigment.uv_mapping);
}

// A fractal's <cr, ci> (POV-Ray's Parse_UV_Vect: a number is both; a
// vector of three or more is an error).
inline runtime::Vector2Function to_complex(const Value& v, const std::string& what) {
    if (v.is<Vector>() && v.as<Vector>().size > 2)
        throw ValueError(what + " is a <cr, ci> of two numbers, not a " + type_name(v));
    return to_vector2(v, what);
}

template <>
struct action<g::pattern_kind> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        std::vector<Value> args = st.values.close_frame();
        const std::string name = st.values.pop_name();
        if (name == "object")
            throw ValueError("the object pattern is written object { OBJECT LIST }");
        if (name == "material_map")
            throw ValueError(
                "material_map opens a texture and comes first in it: texture { material_map { "
                "TYPE \"FILE\" texture { } ... } }");
        const PatternSlot slot = start_pattern(st, in.position(), name);
        const runtime::pattern::Kind* kind = slot.pattern.kind;
        using A = runtime::pattern::Kind::Argument;
        // In a normal, one more number may follow: the amount (bump_size).
        const std::size_t own = kind->argument == A::PointNumber                             ? 2
                                : kind->argument == A::Vector || kind->argument == A::Number ? 1
                                                                                             : 0;
        if (slot.normal && args.size() == own + 1) {
            slot.normal->amount = to_float(args.back(), name + "'s amount");
            args.pop_back();
        }
        const auto count = [&](std::size_t lo, std::size_t hi, const char* what) {
            if (args.size() < lo || args.size() > hi)
                throw ValueError(name + " takes " + what + ", not " + std::to_string(args.size()) +
                                 " values");
        };
        switch (kind->argument) {
            case A::None:
                count(0, 0, slot.normal ? "at most an amount" : "no value after it");
                break;
            case A::Vector: {
                count(1, 1, "one vector (its direction)");
                // POV-Ray normalizes the direction.
                const runtime::Vector3Function v = to_vector3(args[0], name + "'s direction");
                const TimeFunction length = TimeFunction::apply(
                    TimeOp::Sqrt, v.c[0] * v.c[0] + v.c[1] * v.c[1] + v.c[2] * v.c[2]);
                if (length.is_constant() && length.constant() == 0.0)
                    throw ValueError(name + "'s direction is the zero vector");
                for (int i = 0; i < 3; ++i) slot.pattern.vector.c[i] = v.c[i] / length;
                break;
            }
            case A::Number:
                count(1, 1, "one number");
                // (POV-Ray keeps the arms and the iterations as integers.)
                slot.pattern.number[0] =
                    TimeFunction::apply(TimeOp::Int, to_float(args[0], name + "'s number"));
                break;
            case A::PointNumber: {
                // julia <cr, ci>, N (POV-Ray's Parse_UV_Vect: a number is
                // both); the iterations an integer.
                count(2, 2, "a point <cr, ci> and its iterations");
                const runtime::Vector2Function c = to_complex(args[0], name + "'s point");
                slot.pattern.vector.c[0] = c.c[0];
                slot.pattern.vector.c[1] = c.c[1];
                slot.pattern.number[0] =
                    TimeFunction::apply(TimeOp::Int, to_float(args[1], name + "'s iterations"));
                break;
            }
            case A::Own:  // (read by its own rule: never here)
                throw ValueError(name + " is written " + name + " { ... }");
            case A::Colours: {
                // (In a normal or a texture, the normals or textures follow
                // as blocks.)
                if (slot.normal) {
                    count(0, 0, "at most an amount in a normal");
                    break;
                }
                if (slot.texture) {
                    count(0, 0, "its textures as texture { } blocks");
                    break;
                }
                count(0, static_cast<std::size_t>(kind->colours),
                      ("at most " + std::to_string(kind->colours) + " colours").c_str());
                // A blend list: colour i at value i, the kind's default
                // where none is given.
                for (std::size_t i = 0; i < static_cast<std::size_t>(kind->colours); ++i) {
                    runtime::ColourMapEntry e;
                    e.value = static_cast<double>(i);
                    if (i < args.size()) {
                        e.colour = to_colour(args[i], name + "'s colour " + std::to_string(i + 1));
                    } else {
                        const auto& d = kind->default_map[i].colour;
                        e.colour = runtime::ColourFunction{{d[0], d[1], d[2], d[3], d[4]}};
                    }
                    slot.pigment->colour_map.entries.push_back(std::move(e));
                }
                break;
            }
        }
    }
};

// ---- patterns of their own syntax: slope { }, pigment_pattern { }

// [,] AMOUNT after one, in a normal (POV-Ray reads it after any pattern).
template <>
struct action<g::own_pattern_amount> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        const PatternSlot slot = pattern_slot(st, in.position(), "an amount");
        if (slot.normal == nullptr)
            throw ValueError("a number after a pattern is its amount, only in a normal");
        slot.normal->amount = to_float(v, std::string(slot.pattern.kind->name) + "'s amount");
    }
};

template <>
struct action<g::slope_keyword> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        start_pattern(st, in.position(), "slope");
    }
};
template <>
struct action<g::slope_point_at> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        using S = runtime::pattern::kinds::Slope;
        pattern_slot(st, in.position(), "point_at").pattern.number[S::kPointAt] = 1.0;
    }
};
// Whether a slope is written with point_at (its flag is a constant).
inline bool slope_points_at(const runtime::pattern::Pattern& p) {
    const TimeFunction& flag = p.number[runtime::pattern::kinds::Slope::kPointAt];
    return flag.is_constant() && flag.constant() != 0.0;
}
// slope's and its altitude's numbers, each as written (the ranges are
// made when the pattern closes).
template <class Rule>
struct slope_number_action {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        using S = runtime::pattern::kinds::Slope;
        Value v = st.values.pop();
        runtime::pattern::Pattern& p = pattern_slot(st, in.position(), "slope").pattern;
        if constexpr (std::is_same_v<Rule, g::slope_direction>)
            p.vector = to_vector3(v, slope_points_at(p) ? "slope's point_at" : "slope's direction");
        else if constexpr (std::is_same_v<Rule, g::altitude_direction>)
            p.vector2 = to_vector3(v, "slope's altitude");
        else if constexpr (std::is_same_v<Rule, g::slope_low>)
            p.more[S::kSlopeLow] = to_float(v, "slope's low slope");
        else if constexpr (std::is_same_v<Rule, g::slope_high>)
            p.more[S::kSlopeRange] = to_float(v, "slope's high slope");
        else if constexpr (std::is_same_v<Rule, g::altitude_low>)
            p.more[S::kAltitudeLow] = to_float(v, "slope's low altitude");
        else
            p.more[S::kAltitudeRange] = to_float(v, "slope's high altitude");
    }
};
template <>
struct action<g::slope_direction> : slope_number_action<g::slope_direction> {};
template <>
struct action<g::slope_low> : slope_number_action<g::slope_low> {};
template <>
struct action<g::slope_high> : slope_number_action<g::slope_high> {};
template <>
struct action<g::altitude_direction> : slope_number_action<g::altitude_direction> {};
template <>
struct action<g::altitude_low> : slope_number_action<g::altitude_low> {};
template <>
struct action<g::altitude_high> : slope_number_action<g::altitude_high> {};
template <>
struct action<g::altitude_keyword> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        if (slope_points_at(pattern_slot(st, in.position(), "altitude").pattern))
            throw ValueError("slope's altitude cannot go with point_at, as in POV-Ray");
    }
};
// LOW and HIGH into LOW and HIGH - LOW (POV-Ray: a range of zero, HIGH
// equal to a LOW, is none, with a warning); no direction at all is an
// error, as in POV-Ray ("Zero length for both slope and gradient").
inline void close_slope_range(TimeFunction& low, TimeFunction& high, Interpreter& st,
                              const p::position& at, const char* what) {
    if (high.is_constant() && low.is_constant() && high.constant() != 0.0 &&
        high.constant() == low.constant()) {
        st.warn(at, std::string("zero ") + what + " range in slope, ignored (as POV-Ray)");
        low = 0.0;
        high = 0.0;
        return;
    }
    high = high - low;
}
template <>
struct action<g::slope_pattern> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        using S = runtime::pattern::kinds::Slope;
        runtime::pattern::Pattern& p = pattern_slot(st, in.position(), "slope").pattern;
        close_slope_range(p.more[S::kSlopeLow], p.more[S::kSlopeRange], st, in.position(), "slope");
        close_slope_range(p.more[S::kAltitudeLow], p.more[S::kAltitudeRange], st, in.position(),
                          "altitude");
        if (!slope_points_at(p) && !p.vector.depends_on_time() && !p.vector2.depends_on_time()) {
            bool zero = true;
            for (int i = 0; i < 3; ++i)
                zero = zero && p.vector.c[i].constant() == 0.0 && p.vector2.c[i].constant() == 0.0;
            if (zero)
                throw ValueError(
                    "slope's direction and altitude are both of zero length, as "
                    "POV-Ray refuses");
        }
    }
};

// magnet 1|2 mandel N, magnet 1|2 julia <cr, ci>, N (POV-Ray's MAGNET_TOKEN;
// runtime/texture/pattern/kinds/magnet.hpp): the type and the form are
// constants (they pick POV-Ray's pattern), the point and the iterations
// may move with clock.
template <>
struct action<g::magnet_keyword> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        start_pattern(st, in.position(), "magnet");
    }
};
template <>
struct action<g::magnet_type> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        using M = runtime::pattern::kinds::Magnet;
        const Value v = st.values.pop();
        const double type = std::trunc(to_constant(v, "magnet's type"));
        if (type != 1.0 && type != 2.0)
            throw ValueError("magnet's type is 1 or 2, as in POV-Ray, not " +
                             std::to_string(static_cast<long long>(type)));
        pattern_slot(st, in.position(), "magnet").pattern.number[M::kForm] =
            type == 1.0 ? M::kOneMandel : M::kTwoMandel;
    }
};
template <>
struct action<g::magnet_julia> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        using M = runtime::pattern::kinds::Magnet;
        TimeFunction& form = pattern_slot(st, in.position(), "magnet").pattern.number[M::kForm];
        form = form.constant() == M::kOneMandel ? M::kOneJulia : M::kTwoJulia;
    }
};
template <>
struct action<g::magnet_point> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        const Value v = st.values.pop();
        const runtime::Vector2Function c = to_complex(v, "magnet's point");
        runtime::pattern::Pattern& p = pattern_slot(st, in.position(), "magnet").pattern;
        p.vector.c[0] = c.c[0];
        p.vector.c[1] = c.c[1];
    }
};
template <>
struct action<g::magnet_iterations> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        const Value v = st.values.pop();
        pattern_slot(st, in.position(), "magnet").pattern.number[0] =
            TimeFunction::apply(TimeOp::Int, to_float(v, "magnet's iterations"));
    }
};

// function { EXPRESSION } as a pattern: its value is the function's at the
// point in pattern space (runtime/texture/pattern/kinds/function.hpp).
template <>
struct action<g::function_pattern_body> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        const Value v = st.values.pop();
        const auto& f = *v.as<std::shared_ptr<const runtime::UserFunction>>();
        if (!f.unimplemented.empty())
            throw UnsupportedError("the internal function " + f.unimplemented +
                                   " is not implemented by hexant");
        if (!f.components.empty() || f.parameters.size() > 3)
            throw ValueError("a function pattern's function is a number of x, y, z");
        start_pattern(st, in.position(), "function").pattern.function =
            std::make_shared<const runtime::SpaceFunction>(f.body);
    }
};

// object { OBJECT LIST }: the pattern starts with its object's inside test
// (language/scene_queries.hpp), a function of the point and time.
template <>
struct action<g::object_pattern_object> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        const Value v = st.values.pop();
        if (!v.is<runtime::ObjectPtr>())
            throw ValueError("the object pattern needs an object, not a " + type_name(v));
        const runtime::ObjectPtr& object = v.as<runtime::ObjectPtr>();
        std::shared_ptr<const runtime::PointFunction> inside;
        try {
            inside = std::make_shared<const InsideFunction>(
                object, changes_with_clock(*object, st.animation_time()));
        } catch (const runtime::ObjectError& e) {
            throw ValueError(std::string("the object pattern's object: ") + e.what());
        }
        start_pattern(st, in.position(), "object").pattern.function =
            std::make_shared<const runtime::SpaceFunction>(
                TimeFunction::point_call(std::move(inside), 0, TimeFunction::argument(0),
                                         TimeFunction::argument(1), TimeFunction::argument(2)));
    }
};
// One of its two colours (in a pigment), in order: outside, inside.
template <>
struct action<g::object_pattern_colour> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        const Value v = st.values.pop();
        const PatternSlot slot = pattern_slot(st, in.position(), "the object pattern's colour");
        if (slot.pigment == nullptr)
            throw ValueError("the object pattern's list here holds " +
                             std::string(slot.texture ? "textures" : "normals") + ", not colours");
        auto& entries = slot.pigment->colour_map.entries;
        if (entries.size() >= 2 || !slot.pigment->pigment_map.empty())
            throw ValueError("the object pattern takes at most 2 colours or pigments");
        runtime::ColourMapEntry e;
        e.value = static_cast<double>(entries.size());
        e.colour =
            to_colour(v, "the object pattern's colour " + std::to_string(entries.size() + 1));
        entries.push_back(std::move(e));
    }
};
// The colours it was not given are checker's defaults (POV-Ray's
// Check_Default_Map); pigments are filled by close_pigment.
template <>
struct action<g::object_pattern_close> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        const PatternSlot slot = pattern_slot(st, in.position(), "the object pattern");
        if (slot.pigment == nullptr || !slot.pigment->pigment_map.empty()) return;
        auto& entries = slot.pigment->colour_map.entries;
        const runtime::pattern::Kind& kind = *slot.pattern.kind;
        for (std::size_t i = entries.size(); i < 2; ++i) {
            runtime::ColourMapEntry e;
            e.value = static_cast<double>(i);
            const auto& d = kind.default_map[i].colour;
            e.colour = runtime::ColourFunction{{d[0], d[1], d[2], d[3], d[4]}};
            entries.push_back(std::move(e));
        }
    }
};

// density_file df3 "FILE": its voxels read now, found and confined as
// #include's files are.
template <>
struct action<g::density_file_name> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        const Value v = st.values.pop();
        if (!v.is<std::string>())
            throw ValueError("density_file's file is a string, not a " + type_name(v));
        const std::filesystem::path path =
            st.resolve_include(v.as<std::string>(), in.position(), "density file");
        std::shared_ptr<const runtime::pattern::DensityFile> voxels;
        try {
            voxels = std::make_shared<const runtime::pattern::DensityFile>(
                runtime::pattern::DensityFile::read(
                    path, static_cast<std::uint64_t>(st.options.limits.image_pixels)));
        } catch (const std::runtime_error& e) {
            throw ValueError(std::string("density_file: ") + e.what());
        }
        start_pattern(st, in.position(), "density_file").pattern.density_file = std::move(voxels);
    }
};

template <>
struct action<g::pigment_pattern_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        // (A fresh pigment, as POV-Ray's Create_Pigment: not the default.)
        st.blocks.open(std::in_place_type<runtime::Pigment>);
    }
};
template <>
struct action<g::pigment_pattern_body> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        auto& written = st.blocks.edit<runtime::Pigment>(in.position(), "pigment_pattern");
        close_pigment(written);
        auto pigment = std::make_shared<const runtime::Pigment>(std::move(written));
        st.blocks.close();
        start_pattern(st, in.position(), "pigment_pattern").pattern.pigment = std::move(pigment);
    }
};

// A kind's own modifier, as its file under runtime/texture/pattern/kinds/
// declares it (POV-Ray refuses one the pattern does not have); `second`
// a Pair's factor. Returns the warning to give, if any.
inline std::string set_kind_setting(runtime::pattern::Pattern& pattern, const std::string& name,
                                    const Value& v, const Value* second = nullptr) {
    namespace pt = runtime::pattern;
    const pt::Setting* setting = pattern.kind ? pt::find_setting(*pattern.kind, name) : nullptr;
    if (setting == nullptr) {
        std::string owners;
        for (const pt::Kind* k : pt::all_kinds())
            if (pt::find_setting(*k, name))
                owners += (owners.empty() ? "" : " or ") + std::string(k->name);
        throw ValueError(
            name + " belongs to " + owners + ", not to " +
            (pattern.kind ? std::string(pattern.kind->name) : std::string("a plain colour")));
    }
    if (setting->type == pt::Setting::Type::Vector) {
        const runtime::Vector3Function value = to_vector3(v, name);
        if (setting->constant && value.depends_on_time())
            throw ValueError(name + " cannot move with clock");
        pattern.vector = value;
        return {};
    }
    const auto slot = [&pattern](int at) -> TimeFunction& {
        return at < pt::Setting::kMoreSlot
                   ? pattern.number[static_cast<std::size_t>(at)]
                   : pattern.more[static_cast<std::size_t>(at - pt::Setting::kMoreSlot)];
    };
    std::string warning;
    TimeFunction value = to_float(v, name);
    if (setting->constant && value.depends_on_time())
        throw ValueError(name + " cannot move with clock");
    if (setting->integer) {
        // (POV-Ray's (int)Parse_Float(), then its range.)
        const double whole = std::trunc(value.constant());
        if (!(whole >= setting->low && whole <= setting->high)) {
            const std::string range = name + " is " + std::to_string(setting->low) + " to " +
                                      std::to_string(setting->high) + ", not " +
                                      std::to_string(static_cast<long long>(whole));
            if (!setting->warns) throw ValueError(range + ", as POV-Ray refuses");
            warning = range + ": POV-Ray warns so and uses " +
                      std::to_string(static_cast<int>(setting->number));
            value = setting->number;
        } else {
            value = whole;
        }
    }
    slot(setting->slot) = value;
    if (setting->type == pt::Setting::Type::Pair) {
        if (second == nullptr) throw ValueError(name + " takes two numbers");
        slot(setting->slot + 1) = to_float(*second, name + "'s factor");
    }
    return warning;
}

template <>
struct action<g::pattern_setting> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        const std::string name = st.values.pop_name();
        const PatternSlot slot = pattern_slot(st, in.position(), name.c_str());
        runtime::pattern::Pattern& pattern = slot.pattern;
        // Classic turbulence, made by the first of its settings (POV-Ray's Check_Turb).
        const auto turbulence = [&]() -> runtime::pattern::Turbulence& {
            if (!pattern.turbulence) pattern.turbulence.emplace();
            return *pattern.turbulence;
        };
        if (name == "frequency")
            pattern.frequency = to_float(v, "frequency");
        else if (name == "phase")
            pattern.phase = to_float(v, "phase");
        else if (name == "turbulence")
            turbulence().amount = to_vector3(v, "turbulence");
        else if (name == "octaves")
            turbulence().octaves = to_float(v, "octaves");
        else if (name == "omega")
            turbulence().omega = to_float(v, "omega");
        else if (name == "lambda")
            turbulence().lambda = to_float(v, "lambda");
        else if (name == "noise_generator") {
            pattern.noise_generator = static_cast<int>(
                checked_integer(to_constant(v, "noise_generator"), "noise_generator", 1, 3));
        } else {
            const std::string warning = set_kind_setting(pattern, name, v);
            if (!warning.empty()) st.warn(in.position(), warning);
        }
    }
};

// A kind's setting of two numbers: exterior TYPE, FACTOR.
template <>
struct action<g::pattern_pair_setting> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        std::vector<Value> args = st.values.close_frame();
        const std::string name = st.values.pop_name();
        runtime::pattern::Pattern& pattern = pattern_slot(st, in.position(), name.c_str()).pattern;
        if (args.size() != 2) throw ValueError(name + " takes two numbers, TYPE, FACTOR");
        set_kind_setting(pattern, name, args[0], &args[1]);
    }
};

// A kind's setting that is a word alone: 1 in its slot.
template <>
struct action<g::pattern_flag_setting> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        const std::string name = word(in);
        runtime::pattern::Pattern& pattern = pattern_slot(st, in.position(), name.c_str()).pattern;
        set_kind_setting(pattern, name, Value{TimeFunction(1.0)});
    }
};

template <>
struct action<g::pattern_wave> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        std::vector<Value> args = st.values.close_frame();
        const std::string name = st.values.pop_name();
        runtime::pattern::Pattern& pattern = pattern_slot(st, in.position(), name.c_str()).pattern;
        using W = runtime::pattern::Wave;
        if (name != "poly_wave" && !args.empty()) throw ValueError(name + " takes no value");
        pattern.wave = name == "ramp_wave"       ? W::Ramp
                       : name == "sine_wave"     ? W::Sine
                       : name == "triangle_wave" ? W::Triangle
                       : name == "scallop_wave"  ? W::Scallop
                       : name == "cubic_wave"    ? W::Cubic
                                                 : W::Poly;
        if (name == "poly_wave")
            pattern.exponent = args.empty() ? TimeFunction(1.0) : to_float(args[0], "poly_wave");
    }
};

// ---- normal { }
template <>
struct action<g::normal_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        refuse_patterned_edit(st, "normal");
        fold_texture_transform(st);
        std::optional<runtime::Normal> start;
        if (const runtime::Texture* texture = texture_being_written(st))
            start = texture->normal.optional();
        else if (!st.blocks.empty())
            if (const auto* camera = std::get_if<runtime::CameraRecord>(&st.blocks.top()))
                start = camera->normal;
        if (!start) start = st.default_normal_start;
        st.blocks.open(start ? std::move(*start) : runtime::Normal());
    }
};
template <>
struct action<g::normal_base> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        if (!v.is<runtime::Normal>())
            throw ValueError("normal { } starts with a normal, not a " + type_name(v));
        st.blocks.edit<runtime::Normal>(in.position(), "a normal") = v.as<runtime::Normal>();
    }
};
template <>
struct action<g::normal_setting> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        const std::string name = st.values.pop_name();
        auto& normal = st.blocks.edit<runtime::Normal>(in.position(), name.c_str());
        if (name == "bump_size")
            normal.amount = to_float(v, "bump_size");
        else
            normal.accuracy = to_float(v, "accuracy");
    }
};
template <>
struct action<g::normal_no_bump_scale> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        st.blocks.edit<runtime::Normal>(in.position(), "no_bump_scale").no_bump_scale = true;
    }
};
template <>
struct action<g::normal_block> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        auto& normal = st.blocks.edit<runtime::Normal>(in.position(), "a normal");
        // (Only #default's own normal may leave it out: POV-Ray's default Tnormal.)
        const bool default_item = st.default_depth && st.blocks.depth() == *st.default_depth + 1;
        if (normal.patterned->kind == nullptr && normal.unsupported_name.empty() &&
            !normal.bump_map && !default_item)
            throw ValueError("a normal needs a pattern (POV-Ray: no normal type given)");
        check_average(normal.patterned, !normal.normal_map.empty(), "normal_map");
        close_uv_mapping(normal.uv_mapping);
        Value v{std::move(normal)};
        st.blocks.close();
        st.values.push(std::move(v));
    }
};
template <>
struct action<g::texture_normal> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        st.blocks.edit<runtime::Texture>(in.position(), "normal").normal = v.as<runtime::Normal>();
    }
};
template <>
struct action<g::camera_normal> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        check_normal(v.as<runtime::Normal>());
        // (POV-Ray: "The 'uv_mapping' pattern cannot be used" without a surface.)
        if (v.as<runtime::Normal>().uv_mapping != runtime::UvMapping::Off)
            throw ValueError("uv_mapping needs a surface's (u, v): not in the camera's normal");
        st.blocks.edit<runtime::CameraRecord>(in.position(), "normal").normal =
            v.as<runtime::Normal>();
    }
};

// A texture's pattern has its map (POV-Ray: "Patterned texture must have
// texture_map"), a block pattern all its textures.
inline void check_patterned_texture(const runtime::Texture& t) {
    if (t.patterned->kind == nullptr) return;
    if (t.texture_map.empty())
        throw ValueError("a texture with a pattern (" + std::string(t.patterned->kind->name) +
                         ") needs a texture_map, as in POV-Ray");
    using A = runtime::pattern::Kind::Argument;
    if (t.patterned->kind->argument == A::Colours &&
        t.texture_map.size() < static_cast<std::size_t>(t.patterned->kind->colours))
        throw ValueError(std::string(t.patterned->kind->name) + " in a texture needs " +
                         std::to_string(t.patterned->kind->colours) + " textures, not " +
                         std::to_string(t.texture_map.size()));
}

// `top` layered over `under` (POV-Ray's Link_Textures): top's layers, then
// under's. Nothing is layered over or under a patterned texture. Takes the
// time of top's layers only (Texture::below is bottom first).
inline runtime::Texture layered(runtime::Texture top, runtime::Texture under) {
    if (under.is_patterned())
        throw ValueError(
            "a texture cannot be layered over a patterned one (texture_map), as in POV-Ray");
    if (top.is_patterned())
        throw ValueError(
            "a patterned texture (texture_map) cannot be layered over another, as in POV-Ray");
    std::vector<runtime::Texture> layers = std::move(under.below);
    under.below.clear();
    layers.push_back(std::move(under));
    for (auto& layer : top.below) layers.push_back(std::move(layer));
    top.below = std::move(layers);
    return top;
}

}  // namespace hexant::language
