// POV-Ray's mesh and mesh2 in object space: triangles sharing vertices,
// smooth where the face has normals (the shading normal blends the corners'
// as smooth_triangle's), found through the mesh's own hierarchy.
//
// Hits: part = the face's index in MeshData::faces (its texture, if any,
// is MeshData::textures[face.texture]). uv: the face's uv_vectors blended by
// the hit's barycentric weights (POV-Ray's Mesh::UVCoord), else (0, 0), as
// POV-Ray reads a face without uv_vectors. Normals:
// the face's own side (p2 - p1) x (p3 - p1), not flipped toward the ray.
// inside: only with an inside_vector (POV-Ray 3.7: a ray from the point
// along it crossing the faces an odd number of times), else false.
//
// Accuracy: each face is intersect_barycentric's watertight test
// (triangle_geometry.hpp), so rays do not slip between faces sharing an edge.
#pragma once

#include <memory>
#include <optional>

#include "runtime/geometry/ray3.hpp"
#include "runtime/objects/mesh/mesh_data.hpp"

namespace hexant::runtime::geometry {

struct MeshGeometry {
    std::shared_ptr<const objects::MeshData> data;
};

std::optional<SurfaceHit> intersect(const MeshGeometry& mesh, const Ray3& ray, double s_min,
                                    double s_max);
bool inside(const MeshGeometry& mesh, glm::dvec3 p);
Box3 object_bounds(const MeshGeometry& mesh);
bool surface_may_meet(const MeshGeometry& mesh, const Box3& box);

}  // namespace hexant::runtime::geometry
