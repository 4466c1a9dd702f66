// When and how a cell splits (hierarchy.hpp): the paper's criterion and the
// cost criterion, each reading a summary of the cell's contents that the
// builder gathers in one pass over its objects.
#pragma once

#include <array>
#include <cstddef>
#include <limits>

namespace hexant::tracer {

enum class Split { Leaf, Time, Space, Both };

// What the paper's criterion reads.
struct PaperSummary {
    std::size_t objects = 0;
    bool moving = false;     // something in the cell moves
    double occupancy = 0.0;  // the objects' summed occupancy (only when asked)
};

// The paper's rule (Glassner 1988, "Subdivision"): split while more than
// max_objects objects meet the cell, or while more than one fills less than
// max_occupancy of it; time only where something moves, and a lone moving
// object's cell in time only. `space_only` for the frame-by-frame baseline.
Split paper_split(const PaperSummary& s, std::size_t max_objects, double max_occupancy,
                  bool space_only);
// Whether paper_split needs the occupancy (it costs sampling).
inline bool paper_needs_occupancy(const PaperSummary& s, std::size_t max_objects) {
    return s.objects > 1 && s.objects <= max_objects;
}

// What the cost criterion reads: time-averaged surface areas (a piece of
// time's area weighted by its share of the cell's time), of the box of
// everything in a part of the cell ("cell", "half", ...) and of each object's
// own box there, summed over the objects ("object_*"). A bound over some
// time is priced by the boxes over its two halves: a linear-motion box
// follows motion about as well as one more halving does.
//   cell:            the cell, priced over its two time halves;
//   half[h]:         time half h, priced over its quarters;
//   octant[o]:       octant o over the cell's time, over the halves;
//   octant_half[o][h]: octant o over half h, over its quarters.
struct CostSummary {
    std::size_t objects = 0;
    double cell = 0.0;
    std::array<double, 2> half{};
    std::array<double, 8> octant{};
    std::array<std::array<double, 2>, 8> octant_half{};
    double object_cell = 0.0;
    std::array<double, 2> object_half{};
    std::array<double, 8> object_octant{};
    std::array<std::array<double, 2>, 8> object_octant_half{};
    // How many objects meet each part (a leaf of many needs nodes to group
    // them; the children are priced with those too).
    std::array<std::size_t, 2> count_half{};
    std::array<std::size_t, 8> count_octant{};
    std::array<std::array<std::size_t, 2>, 8> count_octant_half{};
    // Looking further in time: with the cell's time cut into 2^k equal
    // pieces (k = 0 .. time_levels), the same areas with each piece's box.
    // One halving of time rarely tightens a fast turn (half a turn sweeps
    // nearly the whole circle); several do.
    static constexpr int kMaxTimeLevels = 7;
    int time_levels = 0;
    std::array<double, kMaxTimeLevels + 1> time_cell{};
    std::array<double, kMaxTimeLevels + 1> time_objects{};
};

// The surface-area heuristic over space and time. A ray at a random instant
// that meets the cell's bound meets a part with probability (part's area) /
// (cell's area), both averaged over the cell's time. Children are priced as
// leaves (greedy, as SAH builders do): a node test (cost 1) plus an object
// test (object_cost) per object bound the ray meets. A time node costs
// nothing (the ray's instant picks the half). Time looks ahead: halving it
// is worth it when cutting it into 2^k pieces pays for some k (the next
// levels then decide again). Leaf when nothing is cheaper.
//
// A split also costs its building: `build` node tests per object reference
// its children hold (the work of clipping sweeps into them, and the memory
// they take). The choice minimises (cost per ray) * rays + build * references,
// with `rays` the rays expected to meet the cell; with rays infinite, the
// plain heuristic. So a cell few rays reach stays a leaf, an animation of
// few rays builds a shallow hierarchy, and of two splits that save alike
// the one that copies fewer objects (time halves copy every object) wins.
struct CostPrices {
    double object = 3.0;  // an object test, in node tests
    double build = 0.0;   // node tests per object to split a cell
    double rays = std::numeric_limits<double>::infinity();
};
Split cost_split(const CostSummary& s, const CostPrices& prices, bool space_only);

// The expected cost per ray of each choice, and the object references its
// children hold (what building it costs), for the statistics and the tests.
struct SplitCosts {
    double leaf, time, space, both;
    double time_refs = 0.0, space_refs = 0.0, both_refs = 0.0;
};
SplitCosts split_costs(const CostSummary& s, double object_cost);

}  // namespace hexant::tracer
