#include "runtime/objects/mesh/mesh_hierarchy.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "runtime/objects/mesh/mesh_data.hpp"

namespace hexant::runtime::objects {

namespace {

struct Builder {
    const std::vector<glm::dvec3>& vertices;
    std::vector<MeshFace>& faces;
    std::vector<glm::dvec3> centres;
    std::vector<std::uint32_t> read;  // the index each face was read at
    std::vector<MeshHierarchy::Node>& nodes;

    geometry::Box3 face_box(const MeshFace& f) const {
        const glm::dvec3 &a = vertices[f.vertex[0]], &b = vertices[f.vertex[1]],
                         &c = vertices[f.vertex[2]];
        return {glm::min(a, glm::min(b, c)), glm::max(a, glm::max(b, c))};
    }

    // Builds the subtree over faces [first, last) at nodes[index].
    void build(std::uint32_t index, std::uint32_t first, std::uint32_t last) {
        geometry::Box3 box = geometry::Box3::nowhere();
        geometry::Box3 centre_box = geometry::Box3::nowhere();
        for (std::uint32_t i = first; i < last; ++i) {
            const geometry::Box3 b = face_box(faces[i]);
            box = {glm::min(box.lo, b.lo), glm::max(box.hi, b.hi)};
            centre_box = {glm::min(centre_box.lo, centres[i]), glm::max(centre_box.hi, centres[i])};
        }
        nodes[index].box = box;
        const std::uint32_t n = last - first;
        if (n <= kMeshLeafSize) {
            nodes[index].first = first;
            nodes[index].count = n;
            return;
        }
        // The median of the centres along the widest axis of their box:
        // balanced, so the depth is log2 of the leaves.
        const glm::dvec3 extent = centre_box.hi - centre_box.lo;
        const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0
                         : extent.y >= extent.z                       ? 1
                                                                      : 2;
        const std::uint32_t mid = first + n / 2;
        std::vector<std::uint32_t> order(n);
        for (std::uint32_t i = 0; i < n; ++i) order[i] = first + i;
        std::nth_element(
            order.begin(), order.begin() + (mid - first), order.end(),
            [&](std::uint32_t a, std::uint32_t b) { return centres[a][axis] < centres[b][axis]; });
        std::vector<MeshFace> f(n);
        std::vector<glm::dvec3> c(n);
        std::vector<std::uint32_t> r(n);
        for (std::uint32_t i = 0; i < n; ++i) {
            f[i] = faces[order[i]];
            c[i] = centres[order[i]];
            r[i] = read[order[i]];
        }
        std::copy(f.begin(), f.end(), faces.begin() + first);
        std::copy(c.begin(), c.end(), centres.begin() + first);
        std::copy(r.begin(), r.end(), read.begin() + first);
        // Left child next to its parent, the right one after the left subtree.
        const std::uint32_t left = index + 1;
        nodes.emplace_back();
        build(left, first, mid);
        const auto right = static_cast<std::uint32_t>(nodes.size());
        nodes[index].first = right;
        nodes[index].count = 0;
        nodes.emplace_back();
        build(right, mid, last);
    }
};

}  // namespace

MeshHierarchy MeshHierarchy::build(const std::vector<glm::dvec3>& vertices,
                                   std::vector<MeshFace>& faces,
                                   std::vector<std::uint32_t>& read_index) {
    MeshHierarchy h;
    read_index.clear();
    if (faces.empty()) return h;
    h.nodes_.reserve(2 * (faces.size() / kMeshLeafSize + 1));
    Builder b{vertices, faces, {}, {}, h.nodes_};
    b.read.resize(faces.size());
    for (std::uint32_t i = 0; i < faces.size(); ++i) b.read[i] = i;
    b.centres.reserve(faces.size());
    for (const auto& f : faces)
        b.centres.push_back(
            (vertices[f.vertex[0]] + vertices[f.vertex[1]] + vertices[f.vertex[2]]) / 3.0);
    h.nodes_.emplace_back();
    b.build(0, 0, static_cast<std::uint32_t>(faces.size()));
    read_index.resize(faces.size());
    for (std::uint32_t i = 0; i < faces.size(); ++i) read_index[b.read[i]] = i;
    return h;
}

bool ray_meets_box(const geometry::Box3& box, const glm::dvec3& origin, const glm::dvec3& inverse,
                   double s_min, double s_max, double& entry) {
    // pbrt-v4's Bounds3::IntersectP: the far ends widened by 1 + 2 gamma(3)
    // so that rounding never drops a box the ray touches. A zero direction
    // component gives an infinite inverse: its slab is all or nothing.
    constexpr double widen = 1.0 + 2.0 * geometry::rounding_gamma(3);  // both ends, either sign
    double lo = s_min, hi = s_max;
    for (int i = 0; i < 3; ++i) {
        double near = (box.lo[i] - origin[i]) * inverse[i];
        double far = (box.hi[i] - origin[i]) * inverse[i];
        if (near > far) std::swap(near, far);
        // 0 * inf (origin on the slab's plane, ray parallel): inside the slab.
        if (std::isnan(near)) near = -std::numeric_limits<double>::infinity();
        if (std::isnan(far)) far = std::numeric_limits<double>::infinity();
        near -= std::fabs(near) * (widen - 1.0);
        far += std::fabs(far) * (widen - 1.0);
        lo = near > lo ? near : lo;
        hi = far < hi ? far : hi;
        if (lo > hi) return false;
    }
    entry = lo;
    return true;
}

}  // namespace hexant::runtime::objects
