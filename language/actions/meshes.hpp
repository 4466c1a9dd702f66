// Meshes: mesh and mesh2, their triangles and vectors.
// Part of the actions (language/actions.hpp).
#pragma once

#include "language/actions/objects.hpp"

namespace hexant::language {

// ------------------------------------------------------------ meshes

// The mesh being read: the object on top of the block stack.
inline runtime::objects::MeshData& mesh_data(Interpreter& st, const p::position& where) {
    auto& record = st.blocks.edit<runtime::ObjectRecord>(where, "a mesh's part");
    auto* mesh = std::get_if<runtime::Mesh>(&record.shape);
    if (!mesh) throw ValueError("this belongs in a mesh or mesh2");
    return *mesh->data;
}
struct open_mesh {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        runtime::ObjectRecord record;
        record.shape = runtime::Mesh{};
        record.place = source_place(in);
        st.blocks.open(std::move(record));
    }
};
template <>
struct action<g::mesh_open> : open_mesh {};
template <>
struct action<g::mesh2_open> : open_mesh {};
template <>
struct action<g::mesh_triangle> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        if (!v.is<runtime::ObjectPtr>())
            throw ValueError("a mesh holds triangles and smooth_triangles only");
        st.count_triangles(1, in.position());
        add_mesh_triangle(mesh_data(st, in.position()), *v.as<runtime::ObjectPtr>());
    }
};
template <>
struct action<g::mesh_inside_vector_value> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        set_inside_vector(mesh_data(st, in.position()), st.values.pop());
    }
};
template <>
struct action<g::mesh_hierarchy_value> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)to_constant(st.values.pop(), "hierarchy");
        (void)in;
    }
};
template <>
struct action<g::mesh2_section_name> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        st.values.push_name(word(in));
    }
};
template <>
struct action<g::mesh2_value> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        // A face counts as it is read (the first value is the count).
        if (!st.mesh2_values.empty() && st.values.top_name() == "face_indices")
            st.count_triangles(1, in.position());
        st.mesh2_values.push_back(mesh_value(st.values.pop(), "a mesh2 section"));
    }
};
template <>
struct action<g::mesh2_values> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)st.values.close_frame();  // each value was taken as it was read
        const std::string section = st.values.pop_name();
        std::vector<MeshValue> values = std::move(st.mesh2_values);
        st.mesh2_values.clear();
        read_mesh2_section(mesh_data(st, in.position()), section, values);
    }
};
template <>
struct action<g::mesh2_texture_list> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        read_mesh2_textures(mesh_data(st, in.position()), st.values.close_frame());
    }
};
// The hierarchy is built once all faces are read, before the modifiers'
// object is pushed as a value.
template <const char* Keyword>
struct close_mesh {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        finish_mesh(mesh_data(st, in.position()), Keyword);
        finish_object::apply(in, st);
    }
};
inline constexpr char kMeshWord[] = "mesh";
inline constexpr char kMesh2Word[] = "mesh2";
template <>
struct action<g::mesh_block> : close_mesh<kMeshWord> {};
template <>
struct action<g::mesh2_block> : close_mesh<kMesh2Word> {};

// blob { }: its components are added as they are read
// (runtime/objects/blob/blob.hpp).
template <>
struct action<g::blob_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        runtime::ObjectRecord record;
        record.shape = runtime::Blob{};
        record.place = source_place(in);
        st.blocks.open(std::move(record));
    }
};
// A component's own modifiers go to a block of its own, an object record
// the objects' transform and texture rules edit as they edit any object's
// (its texture moves with the transforms written after it, as POV-Ray's
// Transform_Blob_Element moves it); the component takes them at its `}`.
template <>
struct action<g::blob_component_kind> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        st.values.push_name(word(in));
        runtime::ObjectRecord component;
        component.shape = runtime::Blob{};
        component.place = source_place(in);
        st.blocks.open(std::move(component));
    }
};
template <>
struct action<g::blob_component> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        std::vector<Value> values = st.values.close_frame();
        const std::string kind = st.values.pop_name();
        runtime::ObjectRecord own = std::move(
            st.blocks.edit<runtime::ObjectRecord>(in.position(), "a blob component's modifiers"));
        st.blocks.close();
        auto& record = st.blocks.edit<runtime::ObjectRecord>(in.position(), "a blob component");
        add_blob_component(record, kind, values, st, in.position());
        set_blob_component_modifiers(record, std::move(own), in.position());
    }
};
template <>
struct action<g::blob_old_component> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        std::vector<Value> values = st.values.close_frame();
        auto& record = st.blocks.edit<runtime::ObjectRecord>(in.position(), "a blob component");
        add_blob_component(record, "component", values, st, in.position());
    }
};
template <>
struct action<g::blob_block> : finish_object {};

// The texture an object modifier changes, made if the object has none: a
// copy of the #default texture, as POV-Ray's Parse_Object_Mods.
inline runtime::Texture& object_texture(Interpreter& st, const p::position& where) {
    auto& record = st.blocks.edit<runtime::ObjectRecord>(where, "a texture");
    if (!record.texture) record.texture = st.scene.default_texture;
    if (record.texture->is_patterned())
        throw ValueError(
            "a pigment, normal or finish cannot be added to a patterned texture (texture_map), as "
            "in "
            "POV-Ray");
    return *record.texture;
}

template <>
struct action<g::object_texture> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        auto& record = st.blocks.edit<runtime::ObjectRecord>(in.position(), "a texture");
        auto texture = v.as<runtime::Texture>();
        // A texture on an object that has one is a layer on top, as in POV-Ray.
        record.texture = record.texture ? layered(std::move(texture), std::move(*record.texture))
                                        : std::move(texture);
    }
};
// interior_texture { }: on one the object has, a layer on top (POV-Ray's
// Link_Textures).
template <>
struct action<g::object_interior_texture> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        auto& record = st.blocks.edit<runtime::ObjectRecord>(in.position(), "an interior_texture");
        auto texture = v.as<runtime::Texture>();
        record.interior_texture = std::make_shared<const runtime::Texture>(
            record.interior_texture ? layered(std::move(texture), *record.interior_texture)
                                    : std::move(texture));
    }
};
// POV-Ray moves a texture's pigment and normal themselves when it moves
// the object (Transform_Textures): one given after the object's
// transforms is not moved by them. hexant keeps those transforms on the
// texture, so the new part starts with their inverse.
inline void undo_texture_transforms(runtime::Transform& part, const runtime::Texture& texture) {
    if (texture.uv_mapping == runtime::UvMapping::Off && !texture.transform.empty())
        part.append(texture.transform.inverse());
}
template <>
struct action<g::object_pigment> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        runtime::Texture& texture = object_texture(st, in.position());
        texture.pigment = v.as<runtime::Pigment>();
        undo_texture_transforms(texture.pigment.transform, texture);
    }
};
template <>
struct action<g::object_normal> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        runtime::Texture& texture = object_texture(st, in.position());
        texture.normal = v.as<runtime::Normal>();
        undo_texture_transforms(texture.normal->transform, texture);
    }
};
template <>
struct action<g::object_finish> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        object_texture(st, in.position()).finish =
            st.finishes.share(std::move(v.as<runtime::Finish>()));
    }
};
template <>
struct action<g::object_interior> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        st.blocks.edit<runtime::ObjectRecord>(in.position(), "interior").interior =
            v.as<runtime::Interior>();
    }
};
template <>
struct action<g::object_material> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        MaterialBuilder m = std::get<MaterialBuilder>(st.blocks.top());
        st.blocks.close();
        auto& record = st.blocks.edit<runtime::ObjectRecord>(in.position(), "material");
        if (m.texture) record.texture = m.texture;
        if (m.interior) record.interior = m.interior;
    }
};
template <>
struct action<g::object_flag> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        std::vector<Value> given = st.values.close_frame();
        const std::string name = st.values.pop_name();
        const bool on = given.empty() || runtime::pov_true(to_constant(given[0], name));
        if (!st.blocks.empty() && std::holds_alternative<runtime::LightRecord>(st.blocks.top()))
            throw ValueError("'" + name + "' does not belong in a light_source");
        auto& record = st.blocks.edit<runtime::ObjectRecord>(in.position(), name.c_str());
        if (name == "no_shadow")
            record.no_shadow = on;
        else if (name == "hollow")
            record.hollow = on;
        else if (name == "inverse")
            record.inverse = on;
        else if (name == "no_image")
            record.no_image = on;
        else if (name == "no_reflection")
            record.no_reflection = on;
        else if (name == "no_radiosity")
            record.no_radiosity = on;
        else if (name == "double_illuminate")
            record.double_illuminate = on;
        else if (name == "global_lights") {
            if (!record.light_group)
                throw ValueError("global_lights belongs in a light_group, not in this object");
            record.light_group->global_lights = on;
        }
        // sturm cannot change the image (language/keyword_rules.cpp).
    }
};
// A setting of the object's kind (runtime/objects/shape_kind.hpp).
template <>
struct action<g::shape_setting> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        std::vector<Value> given = st.values.close_frame();
        const std::string name = st.values.pop_name();
        if (!st.blocks.empty() && std::holds_alternative<runtime::LightRecord>(st.blocks.top()))
            throw ValueError("'" + name + "' does not belong in a light_source");
        auto& record = st.blocks.edit<runtime::ObjectRecord>(in.position(), name.c_str());
        set_shape_setting(record, name, given, st, in.position());
    }
};
// (The same, with vectors for values: uv_vectors.)
template <>
struct action<g::shape_vectors_setting> : action<g::shape_setting> {};
template <>
struct action<g::photons_flag_name> : name_action {};
// One setting of photons { }: the value given, or Allow_Float's 1.
inline double photons_flag_value(Interpreter& st, const std::string& name) {
    std::vector<Value> given = st.values.close_frame();
    if (given.empty()) {
        if (name == "refraction" || name == "reflection")
            throw ValueError("photons' " + name + " takes on or off");
        return 1.0;
    }
    const double x = to_constant(given.at(0), "photons' " + name);
    if (!std::isfinite(x)) throw ValueError("photons' " + name + " must be finite");
    return x;
}
// POV-Ray's CheckPassThru: a target that lets photons pass through cannot
// also refract them; which gives way depends on the one written last.
inline void check_pass_through(runtime::ObjectPhotons& ph, const std::string& last,
                               const p::position& where, Interpreter& st) {
    if (!(ph.pass_through && ph.target > 0.0 && ph.refraction != -1)) return;
    if (last == "target" && ph.refraction == 1) {
        st.warn(where,
                "photons: cannot use pass_through with refraction and target; pass_through "
                "turned off, as POV-Ray does");
        ph.pass_through = false;
        return;
    }
    st.warn(where,
            "photons: cannot use pass_through with refraction and target; refraction turned "
            "off, as POV-Ray does");
    ph.refraction = -1;
}
// An object's photons { } (runtime::ObjectPhotons).
template <>
struct action<g::object_photons_flag> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        const std::string name = st.values.pop_name();
        const double x = photons_flag_value(st, name);
        auto& record = st.blocks.edit<runtime::ObjectRecord>(in.position(), "photons");
        runtime::ObjectPhotons& ph = record.photons;
        const std::int8_t on = static_cast<int>(x) != 0 ? 1 : -1;
        if (name == "target") {
            ph.target = x > 0.0 ? x : 0.0;
        } else if (name == "refraction") {
            ph.refraction = on;
        } else if (name == "reflection") {
            ph.reflection = on;
        } else if (name == "collect") {
            ph.collect = x > 0.0;
        } else if (name == "pass_through") {
            ph.pass_through = static_cast<int>(x) != 0;
        } else if (name == "split_union") {
            // (How POV-Ray shoots at a union's members, one bound or each
            // its own: hexant shoots at the union's bound.)
            if (static_cast<int>(x) != 0) st.not_rendered(in.position(), "split_union");
            return;
        } else {
            throw ValueError("'" + name + "' does not belong in an object's photons { }");
        }
        check_pass_through(ph, name, in.position(), st);
    }
};
// A light's photons { } (runtime::LightPhotons).
template <>
struct action<g::light_photons_flag> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        const std::string name = st.values.pop_name();
        const double x = photons_flag_value(st, name);
        auto& light = st.blocks.edit<runtime::LightRecord>(in.position(), "photons");
        const std::int8_t on = static_cast<int>(x) != 0 ? 1 : -1;
        if (name == "refraction")
            light.photons.refraction = on;
        else if (name == "reflection")
            light.photons.reflection = on;
        else if (name == "area_light") {
            light.photons.area_light = static_cast<int>(x) != 0;
            if (light.photons.area_light)
                st.warn(in.position(),
                        "photons' area_light is read but not rendered as POV-Ray renders it: "
                        "photons are shot from the light's centre, not from its grid");
        } else
            throw ValueError("'" + name + "' does not belong in a light's photons { }");
    }
};
// radiosity { importance I }, an object's or #default's: in (0, 1] as
// POV-Ray requires; below 1 it thins the gathering rays that reach the
// object, which hexant does not: warned there. Returns I.
inline double read_importance(const p::position& where, Interpreter& st) {
    std::vector<Value> given = st.values.close_frame();
    const double importance = to_constant(given.at(0), "radiosity's importance");
    if (!(importance > 0.0 && importance <= 1.0))
        throw ValueError("radiosity's importance must be greater than 0 and at most 1");
    if (importance < 1.0) st.not_rendered(where, "importance");
    return importance;
}
template <>
struct action<g::object_radiosity_importance> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        st.blocks.edit<runtime::ObjectRecord>(in.position(), "radiosity");
        (void)read_importance(in.position(), st);
    }
};
template <>
struct action<g::default_radiosity_importance> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        st.scene.global.radiosity.default_importance = read_importance(in.position(), st);
    }
};

}  // namespace hexant::language
