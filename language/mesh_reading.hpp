// Reading POV-Ray's mesh and mesh2 blocks into runtime::objects::MeshData
// (runtime/objects/mesh/): the grammar's rules for them (grammar.hpp,
// mesh_block and mesh2_block) hand their pieces here. Each throws
// ValueError, which the rule that read the piece places.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "language/value.hpp"
#include "runtime/objects/mesh/mesh_data.hpp"
#include "runtime/objects/object.hpp"

namespace hexant::language {

// A value of a mesh2 section, fixed when read: a number (size 1) or a
// vector of 2 or 3 numbers.
struct MeshValue {
    int size = 1;
    std::array<double, 3> c{};
};
// Throws ValueError for other values and for values that depend on clock.
MeshValue mesh_value(const Value& value, const std::string& section);

// A triangle or smooth_triangle written inside mesh { }: its corners (and
// normals), and its texture if it has one.
void add_mesh_triangle(runtime::objects::MeshData& mesh, const runtime::ObjectRecord& triangle);

// One of mesh2's sections: "vertex_vectors", "normal_vectors",
// "uv_vectors", "face_indices", "normal_indices", "uv_indices"; `values`
// is its count and its values, as written.
void read_mesh2_section(runtime::objects::MeshData& mesh, const std::string& section,
                        const std::vector<MeshValue>& values);
// mesh2's texture_list: its count and its textures.
void read_mesh2_textures(runtime::objects::MeshData& mesh, const std::vector<Value>& values);

void set_inside_vector(runtime::objects::MeshData& mesh, const Value& value);

// After the block: indices checked against what they index (POV-Ray's
// rules: faces without normal_indices or uv_indices take their vertex
// indices when there are normals or uvs), then the hierarchy built.
void finish_mesh(runtime::objects::MeshData& mesh, const std::string& keyword);

}  // namespace hexant::language
