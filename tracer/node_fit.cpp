// Nodes fitted to their children's bounds: a box over the node's time, a
// linear-motion box or a 12-slab bound (cell.hpp), each rounded outward to
// floats (bound_rounding.hpp).
#include <algorithm>
#include <cmath>
#include <limits>

#include "runtime/bounds/slab_bound.hpp"
#include "tracer/bound_rounding.hpp"
#include "tracer/hierarchy_builder.hpp"

namespace hexant::tracer {

using namespace hierarchy_build;

// One node over `time` holding the children's bounds, in the style the
// options ask for (Auto: a linear-motion box where it saves area).
NodeRef Hierarchy::Builder::bound_node(NodeArena& arena, const Interval& time,
                                       const std::vector<Child>& children,
                                       Counters& counters) const {
    BoundStyle style = options_.bounds;
    if (space_only() && style == BoundStyle::Linear) style = BoundStyle::Box;
    std::vector<LinearBox> fits;
    if (style == BoundStyle::Auto) {
        style = BoundStyle::Box;
        if (!space_only() && moves_within(children)) {
            double boxes = 0.0, lines = 0.0;
            fits.reserve(children.size());
            for (const Child& c : children) {
                fits.push_back(fit_linear(c.bins));
                boxes += surface_area(c.bins.hull(time));
                lines += fits.back().mean_area();
            }
            // A motion node tests in about 1.25 times a box node's time.
            if (lines < 0.8 * boxes) style = BoundStyle::Linear;
        }
    }
    switch (style) {
        case BoundStyle::Linear:
            ++counters.motion_nodes;
            return motion_node(arena, time, children, fits);
        case BoundStyle::Slabs:
            ++counters.slab_nodes;
            return slab_node(arena, time, children);
        default:
            ++counters.box_nodes;
            return box_node(arena, time, children);
    }
}

// Does anything change from bin to bin?
bool Hierarchy::Builder::moves_within(const std::vector<Child>& children) {
    for (const Child& c : children)
        for (int b = 1; b < c.bins.count; ++b)
            if (c.bins.bin[b] != c.bins.bin[0]) return true;
    return false;
}

NodeRef Hierarchy::Builder::box_node(NodeArena& arena, const Interval& time,
                                     const std::vector<Child>& children) const {
    BoxNode* node = arena.make<BoxNode>();
    node->children = std::uint32_t(children.size());
    node->t0 = time.lo;
    node->t1 = time.hi;
    for (int i = 0; i < kNodeWidth; ++i) {
        for (int k = 0; k < 3; ++k) fill_empty(node->lo[k], node->hi[k], i);
        if (i >= int(children.size())) continue;
        node->child[i] = children[i].ref;
        const Box4 hull = children[i].bins.hull(time);
        if (hull.is_empty()) continue;
        for (int k = 0; k < 3; ++k) {
            node->lo[k][i] = float_down(hull.lo[k]);
            node->hi[k][i] = float_up(hull.hi[k]);
        }
    }
    return NodeRef::node(RefKind::BoxNode, node);
}

// `fits`: the children's fitted boxes if already made, else empty.
NodeRef Hierarchy::Builder::motion_node(NodeArena& arena, const Interval& time,
                                        const std::vector<Child>& children,
                                        const std::vector<LinearBox>& fits) const {
    MotionNode* node = arena.make<MotionNode>();
    node->children = std::uint32_t(children.size());
    node->t0 = time.lo;
    node->t1 = time.hi;
    node->inverse_span = time.hi > time.lo ? 1.0 / (time.hi - time.lo) : 0.0;
    if (!std::isfinite(node->inverse_span)) node->inverse_span = 0.0;
    // A node over one instant has u = 0 always: its ends are the start
    // values, with no change to evaluate.
    const bool instant = node->inverse_span == 0.0;
    for (int i = 0; i < kNodeWidth; ++i) {
        for (int k = 0; k < 3; ++k) {
            fill_empty(node->lo[k], node->hi[k], i);
            node->dlo[k][i] = node->dhi[k][i] = 0.0f;
        }
        if (i >= int(children.size())) continue;
        node->child[i] = children[i].ref;
        const LinearBox fit = fits.empty() ? fit_linear(children[i].bins) : fits[i];
        if (fit.empty) continue;
        for (int k = 0; k < 3; ++k) {
            const LinearEnd lo = linear_end(fit.lo0[k], instant ? fit.lo0[k] : fit.lo1[k], false);
            const LinearEnd hi = linear_end(fit.hi0[k], instant ? fit.hi0[k] : fit.hi1[k], true);
            node->lo[k][i] = lo.start;
            node->dlo[k][i] = lo.change;
            node->hi[k][i] = hi.start;
            node->dhi[k][i] = hi.change;
        }
    }
    return NodeRef::node(RefKind::MotionNode, node);
}

NodeRef Hierarchy::Builder::slab_node(NodeArena& arena, const Interval& time,
                                      const std::vector<Child>& children) const {
    SlabNode* node = arena.make<SlabNode>();
    node->children = std::uint32_t(children.size());
    node->t0 = time.lo;
    node->t1 = time.hi;
    const double t_max = std::max(std::fabs(time.lo), std::fabs(time.hi));
    for (int i = 0; i < kNodeWidth; ++i) {
        for (int k = 0; k < SlabNode::kSlabs; ++k) fill_empty(node->lo[k], node->hi[k], i);
        if (i >= int(children.size())) continue;
        node->child[i] = children[i].ref;
        runtime::SlabBound b = runtime::SlabBound::empty();
        const int n = children[i].bins.count;
        for (int bin = 0; bin < n; ++bin) {
            // The bin's piece of the node's time, widened by an ulp each
            // way: a box claimed over a little more time still holds.
            const double lo = bin == 0 ? time.lo : time.lo + time.width() * (double(bin) / n);
            const double hi =
                bin + 1 == n ? time.hi : time.lo + time.width() * (double(bin + 1) / n);
            b.add(children[i].bins.bin[bin].box(
                Interval(std::nextafter(lo, -std::numeric_limits<double>::infinity()),
                         std::nextafter(hi, std::numeric_limits<double>::infinity()))));
        }
        if (b.is_empty()) continue;
        for (int k = 0; k < 3; ++k) {
            node->lo[k][i] = float_down(b.lo[k]);
            node->hi[k][i] = float_up(b.hi[k]);
        }
        for (int m = 0; m < 8; ++m) {
            node->lo[3 + m][i] = slab_end(b.lo[4 + m], t_max, false);
            node->hi[3 + m][i] = slab_end(b.hi[4 + m], t_max, true);
        }
    }
    return NodeRef::node(RefKind::SlabNode, node);
}

}  // namespace hexant::tracer
