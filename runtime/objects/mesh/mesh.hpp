// POV-Ray's mesh { triangle { .. } smooth_triangle { .. } ... [inside_vector V] }
// and mesh2 { vertex_vectors { } normal_vectors { } uv_vectors { }
// texture_list { } face_indices { } normal_indices { } uv_indices { }
// [inside_vector V] }: one object over many triangles, with its own
// hierarchy (../box_hierarchy.hpp). The object kind
// (runtime/objects/shape_kind.hpp); its two syntaxes have their own rules
// in the grammar (kOwnSyntax), which fill MeshData.
//
// The triangles are fixed when the scene is read (a vertex that depends on
// clock is refused): a mesh moves, turns and deforms as a whole, by its
// transforms, like any object.
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "runtime/objects/mesh/mesh_data.hpp"
#include "runtime/objects/shape_kind.hpp"

namespace hexant::runtime {

namespace objects {
class MeshModel;
}  // namespace objects

struct Mesh {
    static constexpr std::string_view keyword = "mesh";
    static constexpr bool kOwnSyntax = true;
    using Model = objects::MeshModel;

    // Filled while the block is read, then never changed (copies share it).
    std::shared_ptr<objects::MeshData> data = std::make_shared<objects::MeshData>();

    // The textures its faces name (texture_list, a triangle's texture), in
    // the mesh's own space.
    const std::vector<Texture>& part_textures() const { return data->textures; }
    template <class F>
    void parameters(F&& f) const {
        f("triangles", "triangles",
          objects::DescribedParameter{std::to_string(data->faces.size())});
        f("vertices", "vertices",
          objects::DescribedParameter{std::to_string(data->vertices.size())});
        f("textures", "textures",
          objects::DescribedParameter{std::to_string(data->textures.size())});
        if (data->inside_vector) {
            const glm::dvec3 v = *data->inside_vector;
            f("inside_vector", "inside_vector", Vector3Function{{v.x, v.y, v.z}});
        }
    }
};

}  // namespace hexant::runtime

#include "runtime/objects/mesh/mesh_model.hpp"
