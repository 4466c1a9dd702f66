// Cell splitting: a cell of the hybrid hierarchy halved in time, in space
// (its octants), in both or not at all, as the split criterion chooses
// (split_criterion.hpp), each child built now or left pending for the
// first ray that reaches it (Hierarchy::expand).
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "tracer/hierarchy_builder.hpp"

namespace hexant::tracer {

using namespace hierarchy_build;

// The node of the cell `region` (whose time is `time`) holding
// `objects` (each meets it).
NodeRef Hierarchy::Builder::build(NodeArena& arena, const Box4& region, const CellTime& time,
                                  const ObjectList& list, int depth, Counters& counters) const {
    ++counters.cells;
    arena.count_cell();
    const std::vector<std::uint32_t>& objects = *list;
    if (objects.empty()) return {};
    const Split split = depth < options_.depth_limit()
                            ? choose(region, time, objects, depth, counters)
                            : Split::Leaf;
    switch (split) {
        case Split::Leaf:
            return leaf(arena, region, time, objects, counters);
        case Split::Space:
            return space_node(arena, region, time, list, depth, counters);
        case Split::Time:
        case Split::Both:
            return time_node(arena, region, time, list, depth, split, counters);
    }
    return {};
}

Split Hierarchy::Builder::choose(const Box4& region, const CellTime& time,
                                 const std::vector<std::uint32_t>& objects, int depth,
                                 Counters& counters) const {
    counters.bounds_built += objects.size();
    if (options_.criterion == Criterion::Paper) {
        PaperSummary s;
        s.objects = objects.size();
        for (const std::uint32_t i : objects) s.moving = s.moving || objects_.objects[i]->moves();
        if (paper_needs_occupancy(s, options_.max_objects))
            for (const std::uint32_t i : objects)
                s.occupancy += objects_.objects[i]->occupancy(region);
        return paper_split(s, options_.max_objects, options_.max_occupancy, space_only());
    }
    const CostSummary summary = cost_summary(region, time, objects);
    // The root is built first, alone: every other cell reads this.
    if (depth == 0) h_.root_area_ = summary.cell;
    CostPrices prices;
    prices.object = options_.object_cost;
    if (options_.rays_per_frame > 0.0 && h_.root_area_ > 0.0) {
        prices.build = options_.build_cost;
        // Frames' worth of rays in the cell's time: its length in frames,
        // or, shorter than a frame, its share of one shutter (all of it
        // for a zero shutter: an instant holds a whole frame's rays).
        const double w = time.t.width();
        double frames = 1.0;
        if (options_.frame_interval > 0.0) frames = w / options_.frame_interval;
        if (options_.shutter_time > 0.0)
            frames = std::max(frames, std::min(1.0, w / options_.shutter_time));
        else
            frames = std::max(frames, 1.0);
        prices.rays = options_.rays_per_frame * frames * summary.cell / h_.root_area_;
    }
    return cost_split(summary, prices, space_only());
}

// A child cell: built now (eager) or when a ray first reaches it.
// A child's list: the parent's own where it holds all of the parent's
// objects (a part of a list holds them in the same order).
ObjectList Hierarchy::Builder::shared_list(const ObjectList& parent,
                                           std::vector<std::uint32_t> part) {
    if (part.size() == parent->size()) return parent;
    return std::make_shared<const std::vector<std::uint32_t>>(std::move(part));
}

NodeRef Hierarchy::Builder::child_cell(NodeArena& arena, const Box4& region, const CellTime& time,
                                       ObjectList objects, int depth, Counters& counters) const {
    if (options_.build == BuildKind::Eager)
        return build(arena, region, time, objects, depth, counters);
    PendingCell* p = arena.own<PendingCell>();
    p->arena = &arena;
    // The first cell no longer than a frame below the part that stays:
    // its subtree gets an arena of its own, freed when the frames have
    // passed its time (Hierarchy::release_outside).
    p->slab_root = &arena == &h_.arena_ && !space_only() && options_.frame_interval > 0.0 &&
                   time.t.width() <= options_.frame_interval;
    p->region = region;
    p->time_level = time.level;
    p->time_index = time.index;
    p->object_count = objects ? objects->size() : 0;
    p->objects = std::move(objects);
    p->depth = depth;
    return NodeRef::node(RefKind::Pending, p);
}

// The cell's two time halves, each a child cell (Split::Time) or the
// node of its octants (Split::Both).
NodeRef Hierarchy::Builder::time_node(NodeArena& arena, const Box4& region, const CellTime& time,
                                      const ObjectList& list, int depth, Split split,
                                      Counters& counters) const {
    const std::vector<std::uint32_t>& objects = *list;
    ++counters.time_splits;
    ++counters.time_nodes;
    TimeNode* node = arena.make<TimeNode>();
    std::array<CellTime, 2> times{time.part(1, 0, objects_.time), time.part(1, 1, objects_.time)};
    node->t0 = time.t.lo;
    node->split = times[0].t.hi;
    node->t1 = time.t.hi;
    std::array<Box4, 2> halves{region, region};
    std::array<std::vector<std::uint32_t>, 2> lists;
    for (int h = 0; h < 2; ++h) {
        halves[h].lo.w = times[h].t.lo;
        halves[h].hi.w = times[h].t.hi;
    }
    for (const std::uint32_t i : objects)
        for (int h = 0; h < 2; ++h)
            if (!object_over(i, times[h], halves[h]).is_empty()) lists[h].push_back(i);
    const auto make_half = [&](int h, Counters& c) {
        if (lists[h].empty()) return NodeRef{};
        const ObjectList half = shared_list(list, std::move(lists[h]));
        if (split == Split::Both) return space_node(arena, halves[h], times[h], half, depth, c);
        return child_cell(arena, halves[h], times[h], half, depth + 1, c);
    };
    if (options_.build == BuildKind::Eager && split == Split::Time) {
        std::array<Counters, 2> each;
        tbb::parallel_for(0, 2, [&](int h) { node->child[h] = make_half(h, each[h]); });
        counters += each[0];
        counters += each[1];
    } else {
        // (Split::Both builds its octants in parallel inside.)
        node->child[0] = make_half(0, counters);
        node->child[1] = make_half(1, counters);
    }
    return NodeRef::node(RefKind::TimeNode, node);
}

// The region's octants as the children of one node (those its objects
// meet), each bounded by what its objects occupy inside it.
NodeRef Hierarchy::Builder::space_node(NodeArena& arena, const Box4& region, const CellTime& time,
                                       const ObjectList& list, int depth,
                                       Counters& counters) const {
    const std::vector<std::uint32_t>& objects = *list;
    std::array<Box4, 8> octants;
    for (int o = 0; o < 8; ++o) octants[o] = octant(region, o);
    std::array<std::vector<std::uint32_t>, 8> lists;
    std::array<TimeBins, 8> bins;
    const int k = fit_levels();
    for (auto& b : bins) b = TimeBins::empty(1 << k);
    for (const std::uint32_t i : objects) {
        const TimeBins mine = object_bins(i, region, time, k);
        for (int o = 0; o < 8; ++o) {
            const TimeBins part = mine.clipped(octants[o]);
            if (part.is_empty()) continue;
            bins[o].add(part);
            lists[o].push_back(i);
        }
    }
    std::vector<int> used;
    for (int o = 0; o < 8; ++o)
        if (!lists[o].empty()) used.push_back(o);
    std::vector<Child> children(used.size());
    const auto make = [&](std::size_t c, Counters& counts) {
        const int o = used[c];
        children[c].ref = child_cell(arena, octants[o], time,
                                     shared_list(list, std::move(lists[o])), depth + 1, counts);
        children[c].bins = bins[o];
    };
    if (options_.build == BuildKind::Eager && used.size() > 1) {
        tbb::enumerable_thread_specific<Counters> each;
        tbb::parallel_for(std::size_t(0), used.size(),
                          [&](std::size_t c) { make(c, each.local()); });
        for (const Counters& c : each) counters += c;
    } else {
        for (std::size_t c = 0; c < used.size(); ++c) make(c, counters);
    }
    // A lone child needs no node: the bound that led here holds it.
    if (children.size() == 1) return children.front().ref;
    return bound_node(arena, time.t, children, counters);
}

}  // namespace hexant::tracer
