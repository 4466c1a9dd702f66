#include "runtime/scene/mesh_camera.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include "runtime/objects/mesh/mesh_data.hpp"

namespace hexant::runtime {

namespace {

// The tenth of [0, 1) a uv coordinate falls in, as POV-Ray's int(c * 10)
// capped at 9 (and, where it would index before the first, 0).
int tenth(double c) {
    const double k = std::trunc(c * 10.0);
    return k <= 0.0 ? 0 : k >= 9.0 ? 9 : static_cast<int>(k);
}

glm::dvec2 uv_of(const objects::MeshData& data, const objects::MeshFace& face, int k) {
    // (A face without uv_vectors: POV-Ray's <0, 0> at every corner.)
    return face.uv[k] >= 0 ? data.uvs[static_cast<std::size_t>(face.uv[k])] : glm::dvec2(0.0);
}

}  // namespace

MeshCamera::MeshCamera(unsigned rays_per_pixel, unsigned distribution, double max_distance,
                       bool smooth, std::vector<Mesh> meshes)
    : rays_per_pixel_(rays_per_pixel),
      distribution_(distribution),
      max_distance_(max_distance),
      smooth_(smooth),
      meshes_(std::move(meshes)) {
    // POV-Ray's Parse_Mesh_Camera's rules, in its order.
    if (rays_per_pixel_ == 0) throw std::invalid_argument("rays per pixel may not be 0");
    if (distribution_ > 3)
        throw std::invalid_argument("unrecognized distribution method (0 to 3 are)");
    if ((distribution_ == 2 || distribution_ == 3) && rays_per_pixel_ != 1)
        throw std::invalid_argument("rays per pixel must be 1 for distribution method #2 or #3");
    if (!(max_distance_ >= 0.0)) throw std::invalid_argument("max distance must be 0 or more");
    if (smooth_ && distribution_ != 3)
        throw std::invalid_argument("smooth can only be used with distribution method #3");
    if (meshes_.empty()) throw std::invalid_argument("a mesh camera needs a mesh or mesh2");
    if (distribution_ == 0 && rays_per_pixel_ > meshes_.size())
        throw std::invalid_argument(
            "rays per pixel must be <= number of meshes for distribution method #0");
    std::size_t faces = 0;
    for (const Mesh& mesh : meshes_) summed_.push_back(faces += mesh.faces.size());
    if (distribution_ == 3) {
        // A bit per face in each tenth of u and of v its uv triangle's box
        // reaches (POV-Ray's U_Xref and V_Xref).
        const Mesh& mesh = meshes_.front();
        const std::size_t words = (mesh.faces.size() + 31) / 32;
        for (int i = 0; i < 10; ++i) {
            u_cells_[i].assign(words, 0);
            v_cells_[i].assign(words, 0);
        }
        for (std::size_t i = 0; i < mesh.faces.size(); ++i) {
            const objects::MeshFace& face = mesh.data->faces[mesh.faces[i]];
            int u0 = 9, u1 = 0, v0 = 9, v1 = 0;
            for (int k = 0; k < 3; ++k) {
                const glm::dvec2 uv = uv_of(*mesh.data, face, k);
                u0 = std::min(u0, tenth(uv.x));
                u1 = std::max(u1, tenth(uv.x));
                v0 = std::min(v0, tenth(uv.y));
                v1 = std::max(v1, tenth(uv.y));
            }
            const std::uint32_t bit = 1u << (i % 32);
            for (int u = u0; u <= u1; ++u) u_cells_[u][i / 32] |= bit;
            for (int v = v0; v <= v1; ++v) v_cells_[v][i / 32] |= bit;
        }
    }
}

std::optional<MeshCamera::Ray> MeshCamera::ray(double x, double y, int width, int height,
                                               unsigned number, double offset, bool invert,
                                               double t) const {
    // No pixel outside the image (POV-Ray clips them, negative ones above
    // all, before it turns them into indices).
    x = std::max(0.0, std::min(x, width - 1.0));
    y = std::max(0.0, std::min(y, height - 1.0));
    const auto row = static_cast<std::size_t>(y), column = static_cast<std::size_t>(x);
    const auto w = static_cast<std::size_t>(width);
    switch (distribution_) {
        case 0: {
            const Mesh& mesh = meshes_[number];
            const std::size_t face = row * w + column;
            if (face >= mesh.faces.size()) return std::nullopt;
            return from_face(mesh, mesh.faces[face], offset, invert, t);
        }
        case 1: {
            std::size_t face = row * w + column + number * summed_.back();
            if (face >= summed_.back()) return std::nullopt;
            const auto in = std::upper_bound(summed_.begin(), summed_.end(), face);
            const auto m = static_cast<std::size_t>(in - summed_.begin());
            if (m > 0) face -= summed_[m - 1];
            return from_face(meshes_[m], meshes_[m].faces[face], offset, invert, t);
        }
        case 2: {
            // (POV-Ray's: the mesh by the column, then the face by the whole
            // row's column, not the column within the mesh's part.)
            const std::size_t count = meshes_.size();
            const auto m =
                std::min(static_cast<std::size_t>(x / (double(width) / double(count))), count - 1);
            const std::size_t face = row * (w / count) + column;
            if (face >= meshes_[m].faces.size()) return std::nullopt;
            return from_face(meshes_[m], meshes_[m].faces[face], offset, invert, t);
        }
        default:
            return from_uv((x - 0.5) / width, 1.0 - (y + 0.5) / height, offset, invert, t);
    }
}

std::optional<MeshCamera::Ray> MeshCamera::from_face(const Mesh& mesh, std::uint32_t index,
                                                     double offset, bool invert, double t) const {
    const objects::MeshData& data = *mesh.data;
    const objects::MeshFace& face = data.faces[index];
    const glm::dvec3 &p1 = data.vertices[face.vertex[0]], &p2 = data.vertices[face.vertex[1]],
                     &p3 = data.vertices[face.vertex[2]];
    const glm::dvec3 n = glm::cross(p3 - p1, p2 - p1);
    if (glm::dot(n, n) == 0.0) return std::nullopt;  // (a mesh2's degenerate face)
    return leave(mesh, (p1 + p2 + p3) / 3.0, glm::normalize(n), offset, invert, t);
}

std::optional<MeshCamera::Ray> MeshCamera::leave(const Mesh& mesh, const glm::dvec3& point,
                                                 const glm::dvec3& normal, double offset,
                                                 bool invert, double t) {
    const glm::dvec4 origin(point + offset * normal, 1.0);
    const glm::dmat4 m = mesh.transform.matrix_at(t);
    const glm::dvec3 direction =
        glm::transpose(glm::inverse(glm::dmat3(m))) * (invert ? -normal : normal);
    if (!(glm::dot(direction, direction) > 0.0)) return std::nullopt;
    return Ray{glm::dvec3(m * origin), glm::normalize(direction)};
}

std::optional<MeshCamera::Ray> MeshCamera::from_uv(double u, double v, double offset, bool invert,
                                                   double t) const {
    const Mesh& mesh = meshes_.front();
    const objects::MeshData& data = *mesh.data;
    const auto& us = u_cells_[tenth(u)];
    const auto& vs = v_cells_[tenth(v)];
    for (std::size_t word = 0; word < us.size(); ++word) {
        const std::uint32_t both = us[word] & vs[word];
        for (int bit = 0; bit < 32; ++bit) {
            if (!(both & (1u << bit))) continue;
            const objects::MeshFace& face = data.faces[mesh.faces[word * 32 + bit]];
            const glm::dvec2 a = uv_of(data, face, 0), b = uv_of(data, face, 1),
                             c = uv_of(data, face, 2);
            // The barycentric coordinates of (u, v) in the uv triangle.
            const double scale = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
            if (scale == 0.0) continue;  // (no area: it holds no point)
            const double b1 = ((b.x - u) * (c.y - v) - (c.x - u) * (b.y - v)) / scale;
            const double b2 = ((c.x - u) * (a.y - v) - (a.x - u) * (c.y - v)) / scale;
            const double b3 = ((a.x - u) * (b.y - v) - (b.x - u) * (a.y - v)) / scale;
            if (b1 < 0 || b2 < 0 || b3 < 0) continue;
            const glm::dvec3 &p1 = data.vertices[face.vertex[0]],
                             &p2 = data.vertices[face.vertex[1]],
                             &p3 = data.vertices[face.vertex[2]];
            const glm::dvec3 n = glm::cross(p3 - p1, p2 - p1);
            if (glm::dot(n, n) == 0.0) continue;
            glm::dvec3 normal = glm::normalize(n);
            if (smooth_ && face.smooth())
                normal = b1 * data.normals[static_cast<std::size_t>(face.normal[0])] +
                         b2 * data.normals[static_cast<std::size_t>(face.normal[1])] +
                         b3 * data.normals[static_cast<std::size_t>(face.normal[2])];
            return leave(mesh, b1 * p1 + b2 * p2 + b3 * p3, normal, offset, invert, t);
        }
    }
    return std::nullopt;
}

std::vector<glm::dvec3> MeshCamera::origin_corners(double offset, double t) const {
    std::vector<glm::dvec3> corners;
    const double reach = std::fabs(offset);
    for (const Mesh& mesh : meshes_) {
        glm::dvec3 lo(INFINITY), hi(-INFINITY);
        for (const std::uint32_t f : mesh.faces)
            for (const std::uint32_t v : mesh.data->faces[f].vertex) {
                lo = glm::min(lo, mesh.data->vertices[v]);
                hi = glm::max(hi, mesh.data->vertices[v]);
            }
        if (!(lo.x <= hi.x)) continue;
        lo -= reach;
        hi += reach;
        const glm::dmat4 m = mesh.transform.matrix_at(t);
        for (int k = 0; k < 8; ++k)
            corners.emplace_back(
                m * glm::dvec4(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z, 1.0));
    }
    return corners;
}

}  // namespace hexant::runtime
