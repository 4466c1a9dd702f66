#include "tracer/split_criterion.hpp"

#include <algorithm>
#include <cmath>

#include "tracer/cell.hpp"

namespace hexant::tracer {

Split paper_split(const PaperSummary& s, std::size_t max_objects, double max_occupancy,
                  bool space_only) {
    const bool time = s.moving && !space_only;
    bool space = false;
    if (s.objects > max_objects)
        space = true;
    else if (s.objects > 1)
        space = s.occupancy < max_occupancy;
    // With nothing to separate in space, a moving object's swept bound
    // still tightens when its time is halved.
    if (space && time) return Split::Both;
    if (space) return Split::Space;
    if (time) return Split::Time;
    return Split::Leaf;
}

namespace {

// The node tests a leaf of n objects costs: one, and one per group of a
// node's width beyond it.
double leaf_nodes(std::size_t n) {
    return 1.0 + (n > std::size_t(kNodeWidth) ? std::ceil(double(n) / kNodeWidth) : 0.0);
}

}  // namespace

SplitCosts split_costs(const CostSummary& s, double object_cost) {
    const double a = s.cell;
    SplitCosts c{};
    c.leaf = leaf_nodes(s.objects) + object_cost * s.object_cell / a;
    c.time = 0.0;
    for (int h = 0; h < 2; ++h)
        c.time += (s.half[h] * leaf_nodes(s.count_half[h]) + object_cost * s.object_half[h]) / a;
    // 2^k pieces, each priced over its halves (level k + 1), each holding
    // (at most) all the objects.
    for (int k = 2; k + 1 <= s.time_levels; ++k)
        c.time = std::min(c.time, (s.time_cell[k + 1] * leaf_nodes(s.objects) +
                                   object_cost * s.time_objects[k + 1]) / a);
    c.space = 1.0;
    for (int o = 0; o < 8; ++o)
        c.space += (s.octant[o] * leaf_nodes(s.count_octant[o]) + object_cost * s.object_octant[o]) / a;
    c.both = 0.0;
    for (int h = 0; h < 2; ++h) {
        c.both += s.half[h] / a;
        for (int o = 0; o < 8; ++o)
            c.both += (s.octant_half[o][h] * leaf_nodes(s.count_octant_half[o][h]) +
                       object_cost * s.object_octant_half[o][h]) / a;
    }
    return c;
}

Split cost_split(const CostSummary& s, double object_cost, bool space_only) {
    if (s.objects == 0 || !(s.cell > 0.0) || !std::isfinite(s.cell)) {
        // No area to weigh (a flat or unbounded cell): separate many
        // objects in space, keep few together.
        return s.objects > std::size_t(kNodeWidth) ? Split::Space : Split::Leaf;
    }
    const SplitCosts c = split_costs(s, object_cost);
    // A split must save a little, so that ties (nothing gained) stop.
    constexpr double kGain = 0.98;
    Split best = Split::Leaf;
    double best_cost = c.leaf * kGain;
    const auto consider = [&](Split split, double cost) {
        if (std::isfinite(cost) && cost < best_cost) {
            best = split;
            best_cost = cost;
        }
    };
    consider(Split::Space, c.space);
    if (!space_only && s.time_levels > 0) {
        consider(Split::Time, c.time);
        consider(Split::Both, c.both);
    }
    return best;
}

}  // namespace hexant::tracer
