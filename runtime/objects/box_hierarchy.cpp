#include "runtime/objects/box_hierarchy.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hexant::runtime::objects {

namespace {

struct Builder {
    const std::vector<geometry::Box3>& boxes;
    const std::vector<glm::dvec3>& centres;
    std::vector<std::uint32_t>& order;  // part indices, rearranged in place
    std::vector<BoxHierarchy::Node>& nodes;

    // Builds the subtree over order[first, last) at nodes[index].
    void build(std::uint32_t index, std::uint32_t first, std::uint32_t last) {
        geometry::Box3 box = geometry::Box3::nowhere();
        geometry::Box3 centre_box = geometry::Box3::nowhere();
        for (std::uint32_t i = first; i < last; ++i) {
            const geometry::Box3& b = boxes[order[i]];
            const glm::dvec3& c = centres[order[i]];
            box = {glm::min(box.lo, b.lo), glm::max(box.hi, b.hi)};
            centre_box = {glm::min(centre_box.lo, c), glm::max(centre_box.hi, c)};
        }
        nodes[index].box = box;
        const std::uint32_t n = last - first;
        if (n <= kBoxLeafSize) {
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
        std::nth_element(
            order.begin() + first, order.begin() + mid, order.begin() + last,
            [&](std::uint32_t a, std::uint32_t b) { return centres[a][axis] < centres[b][axis]; });
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

BoxHierarchy BoxHierarchy::build(const std::vector<geometry::Box3>& boxes,
                                 const std::vector<glm::dvec3>& centres,
                                 std::vector<std::uint32_t>& order) {
    BoxHierarchy h;
    order.resize(boxes.size());
    for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    if (boxes.empty()) return h;
    h.nodes_.reserve(2 * (boxes.size() / kBoxLeafSize + 1));
    Builder b{boxes, centres, order, h.nodes_};
    h.nodes_.emplace_back();
    b.build(0, 0, static_cast<std::uint32_t>(boxes.size()));
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
