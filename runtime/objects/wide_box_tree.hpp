// The boxes of a static hierarchy (box_hierarchy.hpp) as rays meet them:
// four children to a node, each child's box in single precision rounded
// outward, the four tested at once (Embree's BVH4; Wald et al., "Getting
// Rid of Packets", 2008). The binary tree is collapsed into it by opening
// the largest inner child until a node has four (box_hierarchy.cpp).
//
// Single precision without missing anything, by the argument of
// tracer/traversal.hpp (Ize, "Robust BVH Ray Traversal", JCGT 2013, carried
// over to floats and rounded origins): the ray keeps each origin coordinate
// rounded to float (off by at most 2^-24 |o|) and each inverse direction
// rounded to float; a computed entry or exit fl(fl(P - o_f) * inv_f) is
// then within 4 * 2^-24 of itself plus |o - o_f| / |d| of the exact one, so
// [near, far] is widened by 2^-20 |x| + epsilon on each side (epsilon twice
// the largest 2^-23 |o| / |d|, plus the smallest normal float for results
// too small to carry a relative error), after clamping infinities to the
// float range. A ray whose numbers leave the range where that holds (a
// coordinate or a direction component of 2^100 or more, or a direction
// component under 2^-100 but not zero) takes the same walk in double
// precision over the same float boxes.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "runtime/geometry/ray3.hpp"

namespace hexant::runtime::objects {

inline constexpr int kWideWidth = 4;

// A ray prepared for the single-precision test.
struct WideRay {
    float origin[3];        // o, rounded
    float inverse[3];       // 1 / d, rounded; 0 where d == 0
    float slack[3];         // d == 0: twice the origin's error, rounded up
    bool negative[3];       // d < 0: a box's upper end is met first
    std::uint8_t parallel;  // bit j: d[j] == 0
    float epsilon;

    // False when the ray's numbers leave the single-precision range.
    bool prepare(const geometry::Ray3& ray);
};

class WideBoxTree {
  public:
    // Child k of a node: an inner node (count[k] == 0, child[k] its index),
    // a leaf (count[k] > 0 parts from child[k] in the hierarchy's order) or
    // an empty slot (its box empty: lo = +inf, hi = -inf, never met).
    struct alignas(64) Node {
        float lo[3][kWideWidth], hi[3][kWideWidth];
        std::uint32_t child[kWideWidth];
        std::uint32_t count[kWideWidth];
    };

    // More levels than any tree BoxHierarchy::build makes (at most
    // kBoxMaxDepth binary levels, each wide level taking at least one of
    // them); the walks' stacks hold three children left behind a level.
    static constexpr int kMaxDepth = 80;

    WideBoxTree() = default;
    explicit WideBoxTree(std::vector<Node> nodes) : nodes_(std::move(nodes)) {}

    bool empty() const { return nodes_.empty(); }
    std::size_t bytes() const { return nodes_.capacity() * sizeof(Node); }
    const Node& node(std::uint32_t i) const { return nodes_[i]; }

    // Calls visit(box, child, count) for each child of the root (empty
    // slots left out), and for each child of an inner child visit returned
    // true for; the box as stored (in doubles, exactly).
    template <class Visit>
    void descend(Visit&& visit) const;

    // As BoxHierarchy::traverse: leaf(first, count, s_max) for every leaf
    // whose box the ray meets within (s_min, s_max), nearer first; leaf
    // returns the new s_max, and the walk ends once s_max <= s_min.
    template <class Leaf>
    void traverse(const geometry::Ray3& ray, double s_min, double s_max, Leaf&& leaf) const;

  private:
    // The children of `node` the ray meets within (s_min, s_max): a bit per
    // child, and their (widened) entry parameters.
    static unsigned meets(const Node& node, const WideRay& r, float s_min, float s_max,
                          float* enter);
    static unsigned meets_double(const Node& node, const geometry::Ray3& ray,
                                 const glm::dvec3& inverse, double s_min, double s_max,
                                 double* enter);
    static float up(double s);

    template <class Real, class Meets, class Up, class Leaf>
    void walk(Real lo, double s_min, double s_max, Meets&& meets, Up&& up, Leaf&& leaf) const;

    std::vector<Node> nodes_;
};

template <class Visit>
void WideBoxTree::descend(Visit&& visit) const {
    if (nodes_.empty()) return;
    std::uint32_t stack[kMaxDepth * (kWideWidth - 1) + kWideWidth];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& n = nodes_[stack[--top]];
        // Last child first on the stack: the first is visited first.
        std::uint32_t inner[kWideWidth];
        int count = 0;
        for (int k = 0; k < kWideWidth; ++k) {
            if (!(n.lo[0][k] <= n.hi[0][k])) continue;  // an empty slot
            const geometry::Box3 box{{n.lo[0][k], n.lo[1][k], n.lo[2][k]},
                                     {n.hi[0][k], n.hi[1][k], n.hi[2][k]}};
            if (visit(box, n.child[k], n.count[k]) && n.count[k] == 0) inner[count++] = n.child[k];
        }
        while (count > 0) stack[top++] = inner[--count];
    }
}

template <class Leaf>
void WideBoxTree::traverse(const geometry::Ray3& ray, double s_min, double s_max,
                           Leaf&& leaf) const {
    if (nodes_.empty() || !(s_min < s_max)) return;
    WideRay r;
    if (r.prepare(ray)) {
        walk<float>(
            -up(-s_min), s_min, s_max,
            [&](const Node& n, float lo, float hi, float* enter) {
                return meets(n, r, lo, hi, enter);
            },
            [](double s) { return up(s); }, leaf);
        return;
    }
    const glm::dvec3 inverse = 1.0 / ray.direction;
    walk<double>(
        s_min, s_min, s_max,
        [&](const Node& n, double lo, double hi, double* enter) {
            return meets_double(n, ray, inverse, lo, hi, enter);
        },
        [](double s) { return s; }, leaf);
}

template <class Real, class Meets, class Up, class Leaf>
void WideBoxTree::walk(Real lo, double s_min, double s_max, Meets&& meets, Up&& up,
                       Leaf&& leaf) const {
    struct Pending {
        std::uint32_t node, slot;
        Real enter;
    };
    Pending stack[kMaxDepth * (kWideWidth - 1) + kWideWidth];
    int top = 0;
    Real hi = up(s_max);
    std::uint32_t node = 0;
    for (;;) {
        Real enter[kWideWidth];
        const unsigned mask = meets(nodes_[node], lo, hi, enter);
        // The children met, farthest first on the stack: the nearest is
        // taken next.
        int index[kWideWidth];
        int count = 0;
        for (unsigned m = mask; m; m &= m - 1) index[count++] = __builtin_ctz(m);
        for (int a = 1; a < count; ++a)
            for (int b = a; b > 0 && enter[index[b]] > enter[index[b - 1]]; --b)
                std::swap(index[b], index[b - 1]);
        for (int k = 0; k < count; ++k)
            stack[top++] = {node, std::uint32_t(index[k]), enter[index[k]]};
        for (;;) {
            if (top == 0) return;
            const Pending p = stack[--top];
            // A box entered at or beyond the nearest hit so far holds
            // nothing nearer (its entry was widened down, never up).
            if (!(p.enter < hi)) continue;
            const Node& n = nodes_[p.node];
            if (n.count[p.slot] == 0) {
                node = n.child[p.slot];
                break;
            }
            s_max = leaf(n.child[p.slot], n.count[p.slot], s_max);
            if (!(s_min < s_max)) return;
            hi = up(s_max);
        }
    }
}

}  // namespace hexant::runtime::objects
