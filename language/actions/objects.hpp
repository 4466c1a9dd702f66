// Objects: shapes, their arguments, settings and modifiers, CSG.
// Part of the actions (language/actions.hpp).
#pragma once

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
        if (const auto* csg = std::get_if<runtime::Csg>(&record.shape)) {
            record.depth = 1;
            for (const auto& child : csg->children)
                record.depth = std::max(record.depth, child->depth + 1);
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
