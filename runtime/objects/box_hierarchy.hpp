// A static hierarchy over the parts of one object, in its own space: a
// mesh's faces (mesh/mesh_data.hpp), an instance's members
// (instance_object.hpp). Built as a binary tree of axis-aligned boxes by the
// surface-area heuristic over binned centres (Wald, "On fast Construction
// of SAH-based Bounding Volume Hierarchies", 2007; pbrt-v4's BVHAggregate),
// leaves of at most kBoxLeafSize parts, then kept only as a four-wide tree
// of single-precision boxes rounded outward (wide_box_tree.hpp). Rays walk
// it nearer children first, skipping a box met beyond the nearest hit so
// far. Its nodes' boxes are the object's bound pieces, finer where a region
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
    // A node as descend() shows it: its box (the root's exact, the others'
    // rounded outward to floats), and for a leaf its parts [first, first +
    // count); count == 0 for an inner node.
    struct Node {
        geometry::Box3 box;
        std::uint32_t first = 0, count = 0;
    };

    // The tree over parts with these boxes and centres (of equal length,
    // at most 2^32 - 1). `order` receives the parts in the tree's leaf
    // order: a leaf's (first, count) names order[first .. first + count),
    // which the caller stores its parts by.
    static BoxHierarchy build(const std::vector<geometry::Box3>& boxes,
                              const std::vector<glm::dvec3>& centres,
                              std::vector<std::uint32_t>& order);

    bool empty() const { return wide_.empty(); }
    // The box over all parts (NaN ends read as unbounded there).
    const geometry::Box3& box() const { return box_; }
    // The binary tree's depth as built (its root at 0), at most kBoxMaxDepth.
    int depth() const { return depth_; }

    // Calls leaf(first, count, s_max) for every leaf whose box the ray
    // meets within (s_min, s_max), nearer first; `leaf` returns the new
    // s_max (the nearest hit so far, or s_max unchanged) and boxes beyond it
    // are skipped. A return of s_min or less (an occluder found: nothing
    // more is wanted) ends the walk.
    template <class Leaf>
    void traverse(const geometry::Ray3& ray, double s_min, double s_max, Leaf&& leaf) const {
        wide_.traverse(ray, s_min, s_max, std::forward<Leaf>(leaf));
    }

    // Calls visit(node) for the root, then for the children of every inner
    // node visit returned true for (descend).
    template <class Visit>
    void descend(Visit&& visit) const {
        if (wide_.empty()) return;
        if (root_leaf_) {
            // (The wide root's one slot.)
            visit(Node{box_, wide_.node(0).child[0], wide_.node(0).count[0]});
            return;
        }
        if (!visit(Node{box_, 0, 0})) return;
        wide_.descend([&](const geometry::Box3& box, std::uint32_t child, std::uint32_t count) {
            return visit(Node{box, child, count});
        });
    }

    // The bytes its nodes hold.
    std::size_t bytes() const { return wide_.bytes(); }

  private:
    geometry::Box3 box_ = geometry::Box3::nowhere();
    int depth_ = 0;
    bool root_leaf_ = false;  // at most kBoxLeafSize parts in all
    WideBoxTree wide_;
};

// The ray's entry and exit of a box within (s_min, s_max), conservative by
// pbrt-v4's rounding factor (1 + 2 gamma(3)) on the far end.
bool ray_meets_box(const geometry::Box3& box, const glm::dvec3& origin, const glm::dvec3& inverse,
                   double s_min, double s_max, double& entry);

}  // namespace hexant::runtime::objects
