// The bound of a moving object over a region of spacetime, from boxes over
// pieces of time: where the box over a piece of time is much larger than the
// object's box at one instant (it swept far, or turned), the piece is halved,
// so a diagonal motion yields a staircase of small 4D boxes that the 12-slab
// bound's diagonal normals follow closely, and a fast turn a thin arc per
// piece rather than one whole circle.
#pragma once

#include <algorithm>
#include <vector>

#include "runtime/bounds/slab_bound.hpp"
#include "runtime/geometry/spacetime.hpp"
#include "runtime/objects/model_support.hpp"
#include "runtime/time/interval.hpp"

namespace hexant::runtime {

// Halving stops at this depth (at most 2^6 = 64 pieces per region) and when
// a piece's box is within this factor of its instant's box: beyond that the
// pieces cost more than the tighter bound saves.
inline constexpr int kSweptBoundMaxDepth = 6;
inline constexpr double kSweptBoundGrowth = 1.5;

inline double largest_width(const IntervalBox& box) {
    return std::max({box[0].width(), box[1].width(), box[2].width()});
}

// The region's part of a world box over a piece of time, as a 4D box (empty
// when they do not meet).
inline Box4 piece_box(const IntervalBox& world, const Interval& time, const Box4& region) {
    Box4 box;
    box.lo = Event(world[0].lo, world[1].lo, world[2].lo, time.lo);
    box.hi = Event(world[0].hi, world[1].hi, world[2].hi, time.hi);
    return box.intersection(region);
}

// world_box_over(Interval t) -> IntervalBox: a conservative world-space box
// of the object's surface over every instant of t. Appends the region's
// non-empty pieces.
template <class WorldBoxOver>
void swept_pieces(const Box4& region, const Interval& time, int depth,
                  WorldBoxOver&& world_box_over, std::vector<Box4>& pieces) {
    const IntervalBox world = world_box_over(time);
    const Box4 piece = piece_box(world, time, region);
    if (piece.is_empty()) return;
    const double mid = time.mid();
    if (depth < kSweptBoundMaxDepth && time.lo < mid && mid < time.hi) {
        const double swept = largest_width(world);
        const double instant = largest_width(world_box_over(Interval(mid)));
        if (swept > kSweptBoundGrowth * instant) {
            swept_pieces(region, Interval(time.lo, mid), depth + 1, world_box_over, pieces);
            swept_pieces(region, Interval(mid, time.hi), depth + 1, world_box_over, pieces);
            return;
        }
    }
    pieces.push_back(piece);
}

// A box's 4D size for comparing bounds, with each extent floored at a
// small fraction of the region's so that flat objects still compare.
inline double bound_size(const Box4& box, const Box4& region) {
    if (box.is_empty()) return 0.0;
    const glm::dvec4 e = box.hi - box.lo, r = region.hi - region.lo;
    double size = 1.0;
    for (int i = 0; i < 4; ++i) size *= std::max(e[i], 1e-3 * r[i]);
    return size;
}

// One 12-slab bound around all pieces, or, when the pieces fall into up to
// four runs whose bounds are together much smaller (a long path swept in a
// loop, the paper's star cluster), one bound per run.
inline void append_swept_bounds(const std::vector<Box4>& pieces, const Box4& region,
                                std::vector<SlabBound>& out) {
    if (pieces.empty()) return;
    SlabBound all = SlabBound::empty();
    for (const Box4& p : pieces) all.add(p);
    all.clip(region);
    constexpr std::size_t kRuns = 4;
    if (pieces.size() >= 2 * kRuns) {
        std::vector<SlabBound> runs;
        double runs_size = 0.0;
        for (std::size_t r = 0; r < kRuns; ++r) {
            const std::size_t begin = r * pieces.size() / kRuns;
            const std::size_t end = (r + 1) * pieces.size() / kRuns;
            SlabBound run = SlabBound::empty();
            for (std::size_t i = begin; i < end; ++i) run.add(pieces[i]);
            run.clip(region);
            runs_size += bound_size(run.box(), region);
            runs.push_back(run);
        }
        if (runs_size < 0.5 * bound_size(all.box(), region)) {
            for (const auto& run : runs)
                if (!run.is_empty()) out.push_back(run);
            return;
        }
    }
    if (!all.is_empty()) out.push_back(all);
}

}  // namespace hexant::runtime
