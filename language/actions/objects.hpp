// Objects: shapes, their arguments, settings and modifiers, CSG.
// Part of the actions (language/actions.hpp).
#pragma once

#include "language/actions/bump_map.hpp"
#include "language/actions/materials.hpp"

namespace hexant::language {

// ------------------------------------------------------------ objects

// Where an object was written.
template <typename ActionInput>
runtime::SourcePlace source_place(const ActionInput& in) {
    const auto p = in.position();
    return {p.source, p.line, p.column};
}

runtime::ObjectRecord make_shape(const Interpreter::ShapeOpening& shape, std::vector<Value>& args,
                                 Interpreter& st, const p::position& where);
void set_shape_setting(runtime::ObjectRecord& record, const std::string& name,
                       std::vector<Value>& values, Interpreter& st, const p::position& where);
// The last blob component's own transforms and texture, from the record its
// modifiers were read into; refuses a deformation there (POV-Ray has none).
void set_blob_component_modifiers(runtime::ObjectRecord& record, runtime::ObjectRecord own,
                                  const p::position& where);
void add_blob_component(runtime::ObjectRecord& record, const std::string& kind,
                        std::vector<Value>& values, Interpreter& st, const p::position& where);

template <>
struct action<g::shape_arguments> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        std::vector<Value> args = st.values.close_frame();
        const Interpreter::ShapeOpening shape = std::move(st.shapes_open.back());
        st.shapes_open.pop_back();
        runtime::ObjectRecord record = make_shape(shape, args, st, in.position());
        record.place = shape.place;
        st.blocks.open(std::move(record));
    }
};

// The host object's limits, to be changed (shared between copies).
inline runtime::ObjectLimits& edit_limits(runtime::ObjectRecord& host) {
    auto limits = host.limits ? std::make_shared<runtime::ObjectLimits>(*host.limits)
                              : std::make_shared<runtime::ObjectLimits>();
    runtime::ObjectLimits& edited = *limits;
    host.limits = std::move(limits);
    return edited;
}
// Finishes the object on top of the block stack and pushes it as a value.
struct finish_object {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Block b = std::move(st.blocks.top());
        st.blocks.close();
        // Made under clock-dependent branches: it exists while they hold.
        if (auto* light = std::get_if<runtime::LightRecord>(&b)) {
            light->lifetime = light->lifetime.intersect(st.domain);
            st.values.push(Value{std::move(*light)});
            return;
        }
        auto& record = std::get<runtime::ObjectRecord>(b);
        record.lifetime = record.lifetime.intersect(st.domain);
        // (POV-Ray's Parse_Object_Mods: "Interior texture requires an
        // exterior texture.")
        if (record.interior_texture && !record.texture)
            Interpreter::fail(in.position(),
                              "an interior_texture needs the object's own texture "
                              "(texture, pigment, normal or finish), as in POV-Ray");
        // A variant of its kind that hexant lacks: usable only where nothing uses it.
        const auto lacking = std::visit(
            [](const auto& shape) -> std::optional<std::string> {
                if constexpr (std::is_same_v<std::decay_t<decltype(shape)>, runtime::Csg>)
                    return std::nullopt;
                else
                    return runtime::objects::unsupported_variant(shape);
            },
            record.shape);
        if (lacking) {
            st.values.push(Value{Unevaluated{*lacking, in.position()}});
            return;
        }
        const auto* csg = std::get_if<runtime::Csg>(&record.shape);
        if (csg || record.limits) {
            record.depth = 1;
            // (Its own, not record.objects: a copy's count holds its limits.)
            std::uint64_t objects = record.own_objects();
            if (csg)
                for (const auto& child : csg->children) {
                    record.depth = std::max(record.depth, child->depth + 1);
                    objects = runtime::add_objects(objects, child->objects);
                }
            if (record.limits) {
                const auto& clips = record.limits->clipped_by;
                for (const auto* list : {&clips, &record.limits->bounded_by})
                    for (const auto& limit : *list) {
                        record.depth = std::max(record.depth, limit->depth + 1);
                        // (A clip is its bound too, unless one is written:
                        // the same record, made once, counted once.)
                        if (list != &clips &&
                            std::find(clips.begin(), clips.end(), limit) != clips.end())
                            continue;
                        objects = runtime::add_objects(objects, limit->objects);
                    }
            }
            record.objects = std::max<std::uint64_t>(objects, 1);
            st.check_object_count(record.objects, in.position());
            if (record.depth > runtime::kMaxObjectDepth)
                Interpreter::fail(in.position(),
                                  "objects nested more than " +
                                      std::to_string(runtime::kMaxObjectDepth) +
                                      " deep (a union built up in a loop? a union of the "
                                      "objects side by side, or an array of them, does not nest)");
        }
        st.values.push(
            Value{runtime::ObjectPtr(std::make_shared<runtime::ObjectRecord>(std::move(record)))});
    }
};
template <>
struct action<g::shape_block> : finish_object {};
template <>
struct action<g::csg_block> : finish_object {};
template <>
struct action<g::object_block> : finish_object {};
template <>
struct action<g::keyword_around_object> : finish_object {};

template <>
struct action<g::csg_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        const std::string kind = st.values.pop_name();
        runtime::Csg csg;
        csg.kind = kind == "intersection" ? runtime::Csg::Kind::Intersection
                   : kind == "difference" ? runtime::Csg::Kind::Difference
                   : kind == "merge"      ? runtime::Csg::Kind::Merge
                                          : runtime::Csg::Kind::Union;
        runtime::ObjectRecord record;
        record.shape = std::move(csg);
        record.place = source_place(in);
        // (A light_group is a union whose lights light its members only;
        // global_lights is off until it says so, as in POV-Ray.)
        if (kind == "light_group") record.light_group = runtime::LightGroupMark{};
        st.blocks.open(std::move(record));
    }
};
template <>
struct action<g::csg_child> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        auto& record = st.blocks.join(in.position());
        if (v.is<runtime::LightRecord>()) {
            record.lights.push_back(v.as<runtime::LightRecord>());
            return;
        }
        if (v.is<Unevaluated>())
            throw UnsupportedError(v.as<Unevaluated>().what + " is not supported by hexant");
        std::get<runtime::Csg>(record.shape).children.push_back(v.as<runtime::ObjectPtr>());
    }
};
// clipped_by { } and bounded_by { }: the word stays on the name stack
// while the block is read (its objects may hold blocks of their own).
template <>
struct action<g::limit_word> : name_action {};
template <>
struct action<g::limit_block> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, Interpreter& st) {
        (void)st.values.pop_name();
    }
};
// `bounded_by { clipped_by }` and `clipped_by { bounded_by }`: the other
// list as it is now (POV-Ray's Parse_Object_Mods, with its errors).
template <>
struct action<g::limit_same> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        const std::string which = st.values.pop_name();
        st.values.push_name(which);
        const std::string other = word(in);
        if (other == which)
            throw ValueError(which + " { " + other + " } names itself; write the objects");
        runtime::ObjectRecord& host =
            st.blocks.edit<runtime::ObjectRecord>(in.position(), which.c_str());
        runtime::ObjectLimits& limits = edit_limits(host);
        auto& mine = which == "clipped_by" ? limits.clipped_by : limits.bounded_by;
        const auto& theirs = which == "clipped_by" ? limits.bounded_by : limits.clipped_by;
        if (!mine.empty())
            throw ValueError("cannot link " + other + " with the " + which +
                             " written before (as POV-Ray)");
        mine = theirs;
    }
};
template <>
struct action<g::limit_object> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        Value v = st.values.pop();
        const std::string which = st.values.pop_name();
        st.values.push_name(which);
        if (v.is<Unevaluated>())
            throw UnsupportedError(v.as<Unevaluated>().what + " is not supported by hexant");
        if (!v.is<runtime::ObjectPtr>())
            throw ValueError(which + " { } takes objects, not a " + type_name(v));
        runtime::ObjectRecord& host =
            st.blocks.edit<runtime::ObjectRecord>(in.position(), which.c_str());
        runtime::ObjectRecord limit = *v.as<runtime::ObjectPtr>();
        // Written in the space around the host: into its object space, so
        // that its later transforms move the limit with it.
        if (!host.transform.empty()) limit.transform.append(host.transform.inverse());
        auto shared = std::make_shared<const runtime::ObjectRecord>(std::move(limit));
        runtime::ObjectLimits& limits = edit_limits(host);
        auto& list = which == "clipped_by" ? limits.clipped_by : limits.bounded_by;
        if (!list.empty() && limits.clipped_by == limits.bounded_by)
            throw ValueError("cannot add to " + which +
                             " after linking clipped_by and bounded_by (as POV-Ray)");
        list.push_back(std::move(shared));
    }
};
template <>
struct action<g::object_base> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        if (v.is<runtime::ObjectPtr>()) {
            runtime::ObjectRecord copy = *v.as<runtime::ObjectPtr>();
            st.blocks.open(std::move(copy));
        } else if (v.is<runtime::LightRecord>()) {
            st.blocks.open(v.as<runtime::LightRecord>());
        } else if (v.is<Unevaluated>()) {
            const auto& u = v.as<Unevaluated>();
            throw UnsupportedError("this " + u.what + " (written at " + u.where.source + ":" +
                                   std::to_string(u.where.line) + ":" +
                                   std::to_string(u.where.column) + ") is not supported by hexant");
        } else {
            throw ValueError("object { } needs an object, not a " + type_name(v));
        }
    }
};

template <>
struct action<g::charset_name> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        const std::string name = in.string();
        // POV-Ray 3.7 on Unix knows ascii and utf8 ("sys" has no conversion there).
        if (name != "ascii" && name != "utf8")
            throw ValueError("charset '" + name +
                             "' is not supported (ascii or utf8, as POV-Ray 3.7 on Unix)");
        st.charset = name;
    }
};

}  // namespace hexant::language
