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

// The node tests a leaf of n objects costs (the cell's own leaf only:
// children are priced as leaves of one node, since they will be split
// further where that pays, as SAH builders price them).
double leaf_nodes(std::size_t n) {
    if (n <= std::size_t(kNodeWidth)) return 1.0;
    // The objects' own small hierarchy (hierarchy.cpp, group): about two
    // node tests per level of eight.
    return 1.0 + 2.0 * std::log(double(n) / kNodeWidth) / std::log(double(kNodeWidth));
}

// The halving of time priced as one level, or as k levels when that is
// cheaper in all (per ray times rays, plus building).
void look_ahead_in_time(const CostSummary& s, double object_cost, double rays, double build,
                        SplitCosts& c) {
    const double a = s.cell;
    const auto total = [&](double per_ray, double refs) {
        return std::isinf(rays) ? per_ray : per_ray * rays + build * refs;
    };
    // 2^k pieces, each priced over its halves (level k + 1), each holding
    // (at most) all the objects: k levels of halving copy them 2^(k+1) - 2
    // times over.
    for (int k = 2; k + 1 <= s.time_levels; ++k) {
        const double cost = (s.time_cell[k + 1] + object_cost * s.time_objects[k + 1]) / a;
        const double refs = double(s.objects) * double((std::size_t(1) << (k + 1)) - 2);
        if (total(cost, refs) < total(c.time, c.time_refs)) {
            c.time = cost;
            c.time_refs = refs;
        }
    }
}

}  // namespace

SplitCosts split_costs(const CostSummary& s, double object_cost) {
    const double a = s.cell;
    SplitCosts c{};
    c.leaf = leaf_nodes(s.objects) + object_cost * s.object_cell / a;
    c.time = 0.0;
    for (int h = 0; h < 2; ++h) {
        c.time += (s.half[h] + object_cost * s.object_half[h]) / a;
        c.time_refs += double(s.count_half[h]);
    }
    c.space = 1.0;
    for (int o = 0; o < 8; ++o) {
        c.space += (s.octant[o] + object_cost * s.object_octant[o]) / a;
        c.space_refs += double(s.count_octant[o]);
    }
    c.both = 0.0;
    for (int h = 0; h < 2; ++h) {
        c.both += s.half[h] / a;
        for (int o = 0; o < 8; ++o) {
            c.both += (s.octant_half[o][h] + object_cost * s.object_octant_half[o][h]) / a;
            c.both_refs += double(s.count_octant_half[o][h]);
        }
    }
    look_ahead_in_time(s, object_cost, std::numeric_limits<double>::infinity(), 0.0, c);
    return c;
}

Split cost_split(const CostSummary& s, const CostPrices& prices, bool space_only) {
    if (s.objects == 0 || !(s.cell > 0.0) || !std::isfinite(s.cell)) {
        // No area to weigh (a flat or unbounded cell): separate many
        // objects in space, keep few together.
        return s.objects > std::size_t(kNodeWidth) ? Split::Space : Split::Leaf;
    }
    SplitCosts c = split_costs(s, prices.object);
    const bool priced = prices.build > 0.0 && std::isfinite(prices.rays);
    if (priced) look_ahead_in_time(s, prices.object, prices.rays, prices.build, c);
    const auto total = [&](double per_ray, double refs) {
        return priced ? per_ray * prices.rays + prices.build * refs : per_ray;
    };
    // A split must save a little, so that ties (nothing gained) stop.
    constexpr double kGain = 0.98;
    Split best = Split::Leaf;
    double best_total = total(c.leaf * kGain, 0.0);
    const auto consider = [&](Split split, double per_ray, double refs) {
        const double t = total(per_ray, refs);
        if (std::isfinite(t) && t < best_total) {
            best = split;
            best_total = t;
        }
    };
    consider(Split::Space, c.space, c.space_refs);
    if (!space_only && s.time_levels > 0) {
        consider(Split::Time, c.time, c.time_refs);
        consider(Split::Both, c.both, c.both_refs);
    }
    return best;
}

}  // namespace hexant::tracer
