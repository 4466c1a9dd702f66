// What a mesh holds once read (mesh { triangle {..} ... } or mesh2 { ... }):
// vertices, normals and uv coordinates shared by index, the faces, the
// textures its faces name, and its hierarchy over the faces in object space
// (../box_hierarchy.hpp). Built once while the scene is read; every copy of
// the object shares it.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "runtime/objects/box_hierarchy.hpp"
#include "runtime/texture/material.hpp"

namespace hexant::runtime::objects {

struct MeshFace {
    std::array<std::uint32_t, 3> vertex{};
    // Indices into normals (all three, or none: -1) and into uvs.
    std::array<std::int32_t, 3> normal{-1, -1, -1};
    std::array<std::int32_t, 3> uv{-1, -1, -1};
    // Index into textures, or -1: the object's own texture.
    std::int32_t texture = -1;

    bool smooth() const { return normal[0] >= 0; }
};

struct MeshData {
    std::vector<glm::dvec3> vertices;
    std::vector<glm::dvec3> normals;
    std::vector<glm::dvec2> uvs;
    std::vector<MeshFace> faces;  // in the hierarchy's order once built
    // Where each face read went in `faces` (the i-th read is
    // faces[read_index[i]]): a mesh camera counts faces in the order read.
    std::vector<std::uint32_t> read_index;
    // Read as mesh2 { } (a mesh { } drops its degenerate triangles, as
    // POV-Ray's does, from what a mesh camera counts).
    bool mesh2 = false;
    std::vector<Texture> textures;
    // POV-Ray's inside_vector: a mesh with one is a solid (a point is inside
    // when a ray from it along the vector crosses the faces an odd number
    // of times); without one it has no inside.
    std::optional<glm::dvec3> inside_vector;
    BoxHierarchy hierarchy;

    // Orders the faces and builds the hierarchy (after reading).
    void build_hierarchy();
    std::size_t bytes() const;
};

}  // namespace hexant::runtime::objects
