#include "runtime/objects/box_hierarchy.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "runtime/geometry/float_rounding.hpp"

namespace hexant::runtime::objects {

namespace {

using geometry::Box3;

constexpr int kBins = 16;

double half_area(const Box3& b) {
    const glm::dvec3 e = b.hi - b.lo;
    return e.x * e.y + e.y * e.z + e.z * e.x;
}

Box3 joined(const Box3& a, const Box3& b) {
    return {glm::min(a.lo, b.lo), glm::max(a.hi, b.hi)};
}

// A part's box with NaN ends read as unbounded there ("anywhere", as
// Box3 says), so that no hull drops it.
Box3 anywhere_for_nan(Box3 b) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) {
        if (std::isnan(b.lo[i])) b.lo[i] = -inf;
        if (std::isnan(b.hi[i])) b.hi[i] = inf;
    }
    return b;
}

// The bin of centre coordinate c among kBins from lo, each 1 / scale wide
// (NaN and anything below lo in the first, anything beyond in the last).
int bin_of(double c, double lo, double scale) {
    const double x = (c - lo) * scale;
    return x > 0.0 ? (x < kBins - 1 ? static_cast<int>(x) : kBins - 1) : 0;
}

struct Builder {
    const std::vector<Box3>& boxes;
    const std::vector<glm::dvec3>& centres;
    std::vector<std::uint32_t>& order;  // part indices, rearranged in place
    std::vector<BoxHierarchy::Node>& nodes;
    int deepest = 0;

    // Builds the subtree over order[first, last) at nodes[index].
    void build(std::uint32_t index, std::uint32_t first, std::uint32_t last, int depth) {
        Box3 box = Box3::nowhere();
        Box3 centre_box = Box3::nowhere();
        for (std::uint32_t i = first; i < last; ++i) {
            box = joined(box, boxes[order[i]]);
            const glm::dvec3& c = centres[order[i]];
            centre_box = {glm::min(centre_box.lo, c), glm::max(centre_box.hi, c)};
        }
        nodes[index].box = box;
        deepest = std::max(deepest, depth);
        const std::uint32_t n = last - first;
        if (n <= kBoxLeafSize) {
            nodes[index].first = first;
            nodes[index].count = n;
            return;
        }
        std::uint32_t mid = depth < kSahDepth ? sah_split(first, last, centre_box) : 0;
        if (mid == 0) mid = median_split(first, last, centre_box);
        // Left child next to its parent, the right one after the left subtree.
        const std::uint32_t left = index + 1;
        nodes.emplace_back();
        build(left, first, mid, depth + 1);
        const auto right = static_cast<std::uint32_t>(nodes.size());
        nodes[index].first = right;
        nodes[index].count = 0;
        nodes.emplace_back();
        build(right, mid, last, depth + 1);
    }

    // The cheapest of the planes between kBins bins of the centres along
    // each axis, by the surface-area heuristic (the children's half areas
    // times their part counts); the partition point, or 0 when no plane
    // parts the centres at a finite cost.
    std::uint32_t sah_split(std::uint32_t first, std::uint32_t last, const Box3& centre_box) {
        double best = std::numeric_limits<double>::infinity();
        int best_axis = -1, best_plane = 0;
        for (int axis = 0; axis < 3; ++axis) {
            const double lo = centre_box.lo[axis], extent = centre_box.hi[axis] - lo;
            if (!(extent > 0.0) || !std::isfinite(extent)) continue;
            const double scale = kBins / extent;
            Box3 bin_box[kBins];
            std::uint32_t bin_count[kBins] = {};
            for (Box3& b : bin_box) b = Box3::nowhere();
            for (std::uint32_t i = first; i < last; ++i) {
                const int b = bin_of(centres[order[i]][axis], lo, scale);
                ++bin_count[b];
                bin_box[b] = joined(bin_box[b], boxes[order[i]]);
            }
            double right_area[kBins];
            std::uint32_t right_count[kBins];
            Box3 sweep = Box3::nowhere();
            std::uint32_t count = 0;
            for (int k = kBins - 1; k > 0; --k) {
                sweep = joined(sweep, bin_box[k]);
                count += bin_count[k];
                right_area[k] = half_area(sweep);
                right_count[k] = count;
            }
            sweep = Box3::nowhere();
            count = 0;
            for (int k = 0; k + 1 < kBins; ++k) {
                sweep = joined(sweep, bin_box[k]);
                count += bin_count[k];
                if (count == 0 || right_count[k + 1] == 0) continue;
                // (An infinite or NaN cost is never below best.)
                const double cost =
                    half_area(sweep) * count + right_area[k + 1] * right_count[k + 1];
                if (cost < best) {
                    best = cost;
                    best_axis = axis;
                    best_plane = k + 1;
                }
            }
        }
        if (best_axis < 0) return 0;
        const double lo = centre_box.lo[best_axis];
        const double scale = kBins / (centre_box.hi[best_axis] - lo);
        const auto split = std::partition(
            order.begin() + first, order.begin() + last,
            [&](std::uint32_t p) { return bin_of(centres[p][best_axis], lo, scale) < best_plane; });
        return static_cast<std::uint32_t>(split - order.begin());
    }

    // The median of the centres along the widest axis of their box:
    // balanced, so each level halves the parts.
    std::uint32_t median_split(std::uint32_t first, std::uint32_t last, const Box3& centre_box) {
        const glm::dvec3 extent = centre_box.hi - centre_box.lo;
        const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0
                         : extent.y >= extent.z                       ? 1
                                                                      : 2;
        // (NaN first: an order, where NaN compares as nothing.)
        const auto key = [&](std::uint32_t p) {
            const double c = centres[p][axis];
            return std::isnan(c) ? -std::numeric_limits<double>::infinity() : c;
        };
        const std::uint32_t mid = first + (last - first) / 2;
        std::nth_element(order.begin() + first, order.begin() + mid, order.begin() + last,
                         [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
        return mid;
    }
};

// The wide node over binary node b's subtree (wide_box_tree.hpp): b's
// children, the one of largest area among the inner ones opened in its
// place until there are four, then a wide node made of each inner one left.
std::uint32_t collapse(const std::vector<BoxHierarchy::Node>& binary, std::uint32_t b,
                       std::vector<WideBoxTree::Node>& wide) {
    std::uint32_t slot[kWideWidth];
    int n = 0;
    if (binary[b].count > 0) {
        slot[n++] = b;  // a root that is a leaf
    } else {
        slot[n++] = b + 1;
        slot[n++] = binary[b].first;
    }
    while (n < kWideWidth) {
        int open = -1;
        double largest = -1.0;
        for (int k = 0; k < n; ++k) {
            if (binary[slot[k]].count > 0) continue;
            const double a = half_area(binary[slot[k]].box);
            const double area = std::isnan(a) ? std::numeric_limits<double>::infinity() : a;
            if (area > largest) {
                largest = area;
                open = k;
            }
        }
        if (open < 0) break;
        const std::uint32_t c = slot[open];
        slot[open] = c + 1;
        slot[n++] = binary[c].first;
    }
    const auto index = static_cast<std::uint32_t>(wide.size());
    wide.emplace_back();
    constexpr float inf = std::numeric_limits<float>::infinity();
    for (int k = 0; k < kWideWidth; ++k) {
        std::uint32_t child = 0, count = 0;
        float lo[3] = {inf, inf, inf}, hi[3] = {-inf, -inf, -inf};  // an empty slot
        if (k < n) {
            const BoxHierarchy::Node& node = binary[slot[k]];
            for (int i = 0; i < 3; ++i) {
                lo[i] = geometry::float_down(node.box.lo[i]);
                hi[i] = geometry::float_up(node.box.hi[i]);
            }
            count = node.count;
            child = node.count > 0 ? node.first : collapse(binary, slot[k], wide);
        }
        // (By index: the recursion may have moved the nodes.)
        WideBoxTree::Node& w = wide[index];
        for (int i = 0; i < 3; ++i) {
            w.lo[i][k] = lo[i];
            w.hi[i][k] = hi[i];
        }
        w.child[k] = child;
        w.count[k] = count;
    }
    return index;
}

}  // namespace

BoxHierarchy BoxHierarchy::build(const std::vector<Box3>& part_boxes,
                                 const std::vector<glm::dvec3>& centres,
                                 std::vector<std::uint32_t>& order) {
    BoxHierarchy h;
    order.resize(part_boxes.size());
    for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    if (part_boxes.empty()) return h;
    std::vector<Box3> boxes;
    boxes.reserve(part_boxes.size());
    for (const Box3& b : part_boxes) boxes.push_back(anywhere_for_nan(b));
    // The binary tree, for the build only (BoxHierarchy::Node's fields:
    // an inner node's children at index + 1 and at `first`).
    std::vector<Node> binary;
    binary.reserve(2 * (boxes.size() / kBoxLeafSize + 1));
    Builder b{boxes, centres, order, binary};
    binary.emplace_back();
    b.build(0, 0, static_cast<std::uint32_t>(boxes.size()), 0);
    h.box_ = binary.front().box;
    h.depth_ = b.deepest;
    h.root_leaf_ = binary.front().count > 0;
    std::vector<WideBoxTree::Node> wide;
    wide.reserve(binary.size() / 3 + 1);
    collapse(binary, 0, wide);
    wide.shrink_to_fit();
    h.wide_ = WideBoxTree(std::move(wide));
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
        // (An infinite end stays as it is: inf - inf would be NaN, which
        // the comparisons below would read as meeting a slab the ray
        // runs beside.)
        if (std::isfinite(near)) near -= std::fabs(near) * (widen - 1.0);
        if (std::isfinite(far)) far += std::fabs(far) * (widen - 1.0);
        lo = near > lo ? near : lo;
        hi = far < hi ? far : hi;
        if (lo > hi) return false;
    }
    entry = lo;
    return true;
}

}  // namespace hexant::runtime::objects
