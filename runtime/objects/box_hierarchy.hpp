// A static hierarchy over the parts of one object, in its own space: a
// mesh's faces (mesh/mesh_data.hpp), an instance's members
// (instance_object.hpp). A binary tree of axis-aligned boxes (Embree's and
// pbrt-v4's BVH, built by splitting at the median of the parts' centres
// along the widest axis), leaves of at most kBoxLeafSize parts. A ray visits
// the nearer child first and skips a box it meets beyond its nearest hit so
// far. It also gives the object's bound pieces: the boxes of its nodes,
// finer where a region is small (the paper's star cluster: an object
// answers bound(region) with several smaller bounds).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "runtime/geometry/ray3.hpp"

namespace hexant::runtime::objects {

inline constexpr std::uint32_t kBoxLeafSize = 4;

class BoxHierarchy {
  public:
    struct Node {
        geometry::Box3 box;
        // A leaf: parts [first, first + count); an inner node (count == 0):
        // children at index + 1 and at `first`.
        std::uint32_t first = 0, count = 0;
    };

    // The tree over parts with these boxes and centres (of equal length,
    // at most 2^32 - 1). `order` receives the parts in the tree's leaf
    // order: a leaf's (first, count) names order[first .. first + count),
    // which the caller stores its parts by.
    static BoxHierarchy build(const std::vector<geometry::Box3>& boxes,
                              const std::vector<glm::dvec3>& centres,
                              std::vector<std::uint32_t>& order);

    bool empty() const { return nodes_.empty(); }
    const std::vector<Node>& nodes() const { return nodes_; }
    const geometry::Box3& box() const { return nodes_.front().box; }

    // Calls leaf(first, count) for every leaf whose box the ray meets within
    // (s_min, s_max), nearer first; `leaf` returns the new s_max (the
    // nearest hit so far, or s_max unchanged) and boxes beyond it are skipped.
    template <class Leaf>
    void traverse(const geometry::Ray3& ray, double s_min, double s_max, Leaf&& leaf) const;

    // Calls visit(index) for nodes from the root down while visit returns
    // true (descend).
    template <class Visit>
    void descend(Visit&& visit) const {
        if (nodes_.empty()) return;
        std::uint32_t stack[64];
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const std::uint32_t i = stack[--top];
            if (!visit(i) || nodes_[i].count > 0) continue;
            stack[top++] = nodes_[i].first;
            stack[top++] = i + 1;
        }
    }

  private:
    std::vector<Node> nodes_;
};

// The ray's entry and exit of a box within (s_min, s_max), conservative by
// pbrt-v4's rounding factor (1 + 2 gamma(3)) on the far end.
bool ray_meets_box(const geometry::Box3& box, const glm::dvec3& origin, const glm::dvec3& inverse,
                   double s_min, double s_max, double& entry);

template <class Leaf>
void BoxHierarchy::traverse(const geometry::Ray3& ray, double s_min, double s_max,
                            Leaf&& leaf) const {
    if (nodes_.empty()) return;
    const glm::dvec3 inverse = 1.0 / ray.direction;
    struct Pending {
        std::uint32_t node;
        double entry;
    };
    Pending stack[64];
    int top = 0;
    double entry = 0.0;
    if (!ray_meets_box(nodes_[0].box, ray.origin, inverse, s_min, s_max, entry)) return;
    stack[top++] = {0, entry};
    while (top > 0) {
        const Pending p = stack[--top];
        if (!(p.entry < s_max)) continue;
        const Node& node = nodes_[p.node];
        if (node.count > 0) {
            s_max = leaf(node.first, node.count, s_max);
            continue;
        }
        const std::uint32_t a = p.node + 1, b = node.first;
        double ea = 0.0, eb = 0.0;
        const bool ha = ray_meets_box(nodes_[a].box, ray.origin, inverse, s_min, s_max, ea);
        const bool hb = ray_meets_box(nodes_[b].box, ray.origin, inverse, s_min, s_max, eb);
        // The nearer one on top of the stack.
        if (ha && hb) {
            if (ea <= eb) {
                stack[top++] = {b, eb};
                stack[top++] = {a, ea};
            } else {
                stack[top++] = {a, ea};
                stack[top++] = {b, eb};
            }
        } else if (ha) {
            stack[top++] = {a, ea};
        } else if (hb) {
            stack[top++] = {b, eb};
        }
    }
}

}  // namespace hexant::runtime::objects
