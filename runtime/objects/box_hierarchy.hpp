// A static hierarchy over the parts of one object, in its own space: a
// mesh's faces (mesh/mesh_data.hpp), an instance's members
// (instance_object.hpp). Built as a binary tree of axis-aligned boxes by the
// surface-area heuristic over binned centres (Wald, "On fast Construction
// of SAH-based Bounding Volume Hierarchies", 2007; pbrt-v4's BVHAggregate),
// leaves of at most kBoxLeafSize parts. Rays walk it as a four-wide tree of
// single-precision boxes (wide_box_tree.hpp), nearer children first,
// skipping a box met beyond the nearest hit so far. The binary tree gives
// the object's bound pieces: the boxes of its nodes, finer where a region
// is small (the paper's star cluster: an object answers bound(region) with
// several smaller bounds).
#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "runtime/geometry/ray3.hpp"
#include "runtime/objects/wide_box_tree.hpp"

namespace hexant::runtime::objects {

inline constexpr std::uint32_t kBoxLeafSize = 4;
// The binary tree's depth at most: the heuristic's splits down to
// kSahDepth, then the median's (a level per halving, at most 31 more for
// 2^32 parts).
inline constexpr int kSahDepth = 40;
inline constexpr int kBoxMaxDepth = kSahDepth + 32;
static_assert(kBoxMaxDepth <= WideBoxTree::kMaxDepth);

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

    // Calls leaf(first, count, s_max) for every leaf whose box the ray
    // meets within (s_min, s_max), nearer first; `leaf` returns the new
    // s_max (the nearest hit so far, or s_max unchanged) and boxes beyond it
    // are skipped. A return of s_min or less (an occluder found: nothing
    // more is wanted) ends the walk.
    template <class Leaf>
    void traverse(const geometry::Ray3& ray, double s_min, double s_max, Leaf&& leaf) const {
        wide_.traverse(ray, s_min, s_max, std::forward<Leaf>(leaf));
    }

    // The bytes its nodes hold.
    std::size_t bytes() const { return nodes_.capacity() * sizeof(Node) + wide_.bytes(); }

    // Calls visit(index) for nodes from the root down while visit returns
    // true (descend).
    template <class Visit>
    void descend(Visit&& visit) const {
        if (nodes_.empty()) return;
        std::uint32_t stack[kBoxMaxDepth + 2];
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
    WideBoxTree wide_;
};

// The ray's entry and exit of a box within (s_min, s_max), conservative by
// pbrt-v4's rounding factor (1 + 2 gamma(3)) on the far end.
bool ray_meets_box(const geometry::Box3& box, const glm::dvec3& origin, const glm::dvec3& inverse,
                   double s_min, double s_max, double& entry);

}  // namespace hexant::runtime::objects
