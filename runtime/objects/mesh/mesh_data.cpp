#include "runtime/objects/mesh/mesh_data.hpp"

namespace hexant::runtime::objects {

void MeshData::build_hierarchy() {
    std::vector<geometry::Box3> boxes;
    std::vector<glm::dvec3> centres;
    boxes.reserve(faces.size());
    centres.reserve(faces.size());
    for (const MeshFace& f : faces) {
        const glm::dvec3 &a = vertices[f.vertex[0]], &b = vertices[f.vertex[1]],
                         &c = vertices[f.vertex[2]];
        boxes.push_back({glm::min(a, glm::min(b, c)), glm::max(a, glm::max(b, c))});
        centres.push_back((a + b + c) / 3.0);
    }
    std::vector<std::uint32_t> order;
    hierarchy = BoxHierarchy::build(boxes, centres, order);
    // The faces in leaf order; the k-th read is where it went.
    std::vector<MeshFace> ordered;
    ordered.reserve(faces.size());
    read_index.assign(faces.size(), 0);
    for (std::uint32_t k = 0; k < order.size(); ++k) {
        ordered.push_back(faces[order[k]]);
        read_index[order[k]] = k;
    }
    faces = std::move(ordered);
}

std::size_t MeshData::bytes() const {
    return vertices.capacity() * sizeof(glm::dvec3) + normals.capacity() * sizeof(glm::dvec3) +
           uvs.capacity() * sizeof(glm::dvec2) + faces.capacity() * sizeof(MeshFace) +
           read_index.capacity() * sizeof(std::uint32_t) + hierarchy.bytes() +
           textures.size() * sizeof(Texture);
}

}  // namespace hexant::runtime::objects
