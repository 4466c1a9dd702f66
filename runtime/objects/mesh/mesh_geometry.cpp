#include "runtime/objects/mesh/mesh_geometry.hpp"

#include <cmath>
#include <limits>

#include "runtime/geometry/box_queries.hpp"
#include "runtime/geometry/stable_arithmetic.hpp"
#include "runtime/objects/triangle/triangle_geometry.hpp"

namespace hexant::runtime::geometry {

namespace {

bool unit(const glm::dvec3& v, glm::dvec3& out) {
    const double len = safe_length(v);
    if (!(len > 0.0) || !std::isfinite(len)) return false;
    out = v / len;
    return true;
}

bool boxes_meet(const Box3& a, const Box3& b) {
    return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y &&
           a.lo.z <= b.hi.z && b.lo.z <= a.hi.z;
}

}  // namespace

std::optional<SurfaceHit> intersect(const MeshGeometry& mesh, const Ray3& ray, double s_min,
                                    double s_max) {
    const objects::MeshData& m = *mesh.data;
    std::optional<BarycentricHit> best;
    std::uint32_t best_face = 0;
    m.hierarchy.traverse(
        ray, s_min, s_max, [&](std::uint32_t first, std::uint32_t count, double s_far) {
            for (std::uint32_t i = first; i < first + count; ++i) {
                const auto& f = m.faces[i];
                const auto hit =
                    intersect_barycentric(m.vertices[f.vertex[0]], m.vertices[f.vertex[1]],
                                          m.vertices[f.vertex[2]], ray, s_min, s_far);
                if (hit) {
                    best = hit;
                    best_face = i;
                    s_far = hit->s;
                }
            }
            return s_far;
        });
    if (!best) return std::nullopt;
    const auto& f = m.faces[best_face];
    const glm::dvec3 &p1 = m.vertices[f.vertex[0]], &p2 = m.vertices[f.vertex[1]],
                     &p3 = m.vertices[f.vertex[2]];
    SurfaceHit hit;
    if (!unit(glm::cross(p2 - p1, p3 - p1), hit.normal)) return std::nullopt;  // a sliver: no hit
    hit.s = best->s;
    hit.shading_normal = hit.normal;
    glm::dvec3 blend;
    if (f.smooth() && unit(best->b1 * m.normals[f.normal[0]] + best->b2 * m.normals[f.normal[1]] +
                               best->b3 * m.normals[f.normal[2]],
                           blend))
        hit.shading_normal = blend;
    hit.uv = f.uv[0] >= 0
                 ? best->b1 * m.uvs[f.uv[0]] + best->b2 * m.uvs[f.uv[1]] + best->b3 * m.uvs[f.uv[2]]
                 : glm::dvec2(0.0);
    hit.part = static_cast<int>(best_face);
    place_barycentric_hit(*best, p1, p2, p3, ray, hit);
    if (!is_finite(hit)) return std::nullopt;
    return hit;
}

bool inside(const MeshGeometry& mesh, glm::dvec3 p) {
    const objects::MeshData& m = *mesh.data;
    if (!m.inside_vector || m.hierarchy.empty()) return false;
    // Every crossing along the inside_vector from p, counted once per face.
    const Ray3 ray{p, *m.inside_vector};
    int crossings = 0;
    m.hierarchy.traverse(
        ray, 0.0, std::numeric_limits<double>::infinity(),
        [&](std::uint32_t first, std::uint32_t count, double s_far) {
            for (std::uint32_t i = first; i < first + count; ++i) {
                const auto& f = m.faces[i];
                if (intersect_barycentric(m.vertices[f.vertex[0]], m.vertices[f.vertex[1]],
                                          m.vertices[f.vertex[2]], ray, 0.0, s_far))
                    ++crossings;
            }
            return s_far;
        });
    return crossings % 2 == 1;
}

Box3 object_bounds(const MeshGeometry& mesh) {
    if (mesh.data->hierarchy.empty()) return Box3::nowhere();
    return mesh.data->hierarchy.box();
}

bool surface_may_meet(const MeshGeometry& mesh, const Box3& box) {
    const objects::MeshData& m = *mesh.data;
    bool met = false;
    m.hierarchy.descend([&](const objects::BoxHierarchy::Node& node) {
        if (met) return false;
        if (!boxes_meet(node.box, box)) return false;
        if (node.count == 0) return true;
        for (std::uint32_t i = node.first; i < node.first + node.count && !met; ++i) {
            const auto& f = m.faces[i];
            met = triangle_may_meet(m.vertices[f.vertex[0]], m.vertices[f.vertex[1]],
                                    m.vertices[f.vertex[2]], box);
        }
        return false;
    });
    return met;
}

}  // namespace hexant::runtime::geometry
