// The bounds of a shape that does not change, carried by its motion: a
// primitive of a fixed shape and an instance's members
// (instance_object.hpp) answer bound(), box_over() and chord_bound_over()
// alike from the world box over a time (the placed box's interval over it).
#pragma once

#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "runtime/bounds/swept_bound.hpp"
#include "runtime/motion/motion.hpp"
#include "runtime/objects/intelligent_object.hpp"
#include "runtime/objects/model_support.hpp"

namespace hexant::runtime {

// IntelligentObject::bound over `region` (not empty): where the shape
// stands still, its one world box `still` clipped to the region; else the
// swept pieces (swept_bound.hpp) of `world_box_over`, a callable from an
// Interval of time to the IntervalBox that holds the shape over it.
template <class WorldBoxOver>
void append_rigid_bounds(const Box4& region, bool moves, const IntervalBox& still,
                         const WorldBoxOver& world_box_over, std::vector<SlabBound>& out) {
    if (!moves) {
        const Box4 piece = piece_box(still, region.time(), region);
        if (piece.is_empty()) return;
        SlabBound b = SlabBound::empty();
        b.add(piece);
        b.clip(region);
        if (!b.is_empty()) out.push_back(b);
        return;
    }
    std::vector<Box4> pieces;
    swept_pieces(region, region.time(), 0, world_box_over, pieces);
    append_swept_bounds(pieces, region, out);
}

// IntelligentObject::box_over: the world box over t (not empty) with t as
// its time.
inline Box4 box_over_time(const IntervalBox& world, const Interval& t) {
    Box4 box;
    box.lo = Event(world[0].lo, world[1].lo, world[2].lo, t.lo);
    box.hi = Event(world[0].hi, world[1].hi, world[2].hi, t.hi);
    return box;
}

// Over t, the motion's second derivative (interval jets, interval_jet.hpp)
// applied to the object box p, x'' = M''(t) (p, 1); the margin is twice the
// matrix entries' rounding radii times |p| (the exact ends against the
// double placed boxes, and the double placement at t against the exact
// one) plus the rounding of the product M (p, 1) itself. Nothing when the
// motion is not smooth over t (a jump or a kink) or the bound overflows.
// `motion` must be affine.
inline std::optional<IntelligentObject::ChordBound> rigid_chord_bound(const Motion& motion,
                                                                      const IntervalBox& p,
                                                                      const Interval& t) {
    const AffineMap<IntervalJet> m = motion.matrix_jet_over(t);
    constexpr double kProductRounding = 4.0 * std::numeric_limits<double>::epsilon();
    IntelligentObject::ChordBound bound;
    for (int i = 0; i < 3; ++i) {
        if (!m.m[i][3].smooth()) return std::nullopt;
        Interval second = m.m[i][3].dd;
        double radius = m.m[i][3].r, magnitude = m.m[i][3].v.magnitude();
        for (int j = 0; j < 3; ++j) {
            if (!m.m[i][j].smooth()) return std::nullopt;
            second = second + m.m[i][j].dd * p[j];
            radius += m.m[i][j].r * p[j].magnitude();
            magnitude += m.m[i][j].v.magnitude() * p[j].magnitude();
        }
        bound.acceleration[i] = second.magnitude();
        bound.margin[i] = interval_detail::up(2.0 * radius + kProductRounding * magnitude, 4);
        if (!std::isfinite(bound.acceleration[i]) || !std::isfinite(bound.margin[i]))
            return std::nullopt;
    }
    return bound;
}

}  // namespace hexant::runtime
