#include "runtime/objects/mesh/mesh_data.hpp"

namespace hexant::runtime::objects {

std::size_t MeshData::bytes() const {
    return vertices.capacity() * sizeof(glm::dvec3) + normals.capacity() * sizeof(glm::dvec3) +
           uvs.capacity() * sizeof(glm::dvec2) + faces.capacity() * sizeof(MeshFace) +
           read_index.capacity() * sizeof(std::uint32_t) +
           hierarchy.nodes().capacity() * sizeof(MeshHierarchy::Node) +
           textures.size() * sizeof(Texture);
}

}  // namespace hexant::runtime::objects
