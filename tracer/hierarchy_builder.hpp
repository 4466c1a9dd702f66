// The builder of the hybrid hierarchy (tracer/hierarchy.hpp), one class
// whose parts live in a file each, as Embree keeps its BVH builders'
// (kernels/bvh/): cell splitting (cell_split.cpp), the price of a split
// (cell_cost.cpp), the leaf's own hierarchy over its objects
// (leaf_hierarchy.cpp) and the nodes fitted to children's bounds
// (node_fit.cpp). The lazy hierarchy that calls it, and its statistics,
// are hierarchy.cpp and hierarchy_statistics.cpp. Private to the tracer.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "runtime/geometry/spacetime.hpp"
#include "tracer/hierarchy.hpp"
#include "tracer/linear_bound.hpp"
#include "tracer/packed_bins.hpp"
#include "tracer/split_criterion.hpp"

namespace hexant::tracer {

namespace hierarchy_build {

using runtime::Box4;
using runtime::Interval;

// Work on fewer objects than this stays on one thread.
inline constexpr std::size_t kParallelGrain = 1024;

// The cost criterion prices a cell of more objects than this from an even
// sample of this many (every (n / kCostSample)-th, the same in every run):
// its sums of the objects' areas and counts scaled up by n / kCostSample,
// the boxes over everything (the cell's, its halves' and octants') the
// sample's union. A price is an estimate anyway (large-BVH builders bin a
// sample likewise); pricing every object of a slab of 10^5 moving spheres
// cost more than building its nodes (swarm, 4 frames of 16: 20 s of the
// render's 25 were cells built, half of it this pass over 10^5 objects at up
// to 2^7 pieces of time each). A sample of 4,096 still took 11% of the
// build's instructions at 10^4 swarm spheres, and chose the same cells as
// this one. The choice changes which cells are built, never an answer
// (tests/tracer: lazy and eager, both criteria, same images).
inline constexpr std::size_t kCostSample = 1024;

// Bounds are fitted to this many equal pieces (bins) of a node's time:
// four, one to each piece of a PieceNode (its fewest). Eight made the
// bounds of the swarm's fastest spheres tighter (1.86 object tests a ray
// at 10^4, 2.06 with four) but the leaves' build, which works per bin
// (the chords, packing, the fits), took 38% longer there, the whole run
// 16-18% longer at 10^4 and 10^5, and no example ran faster (issue 43).
inline constexpr int kFitLevels = 2;
inline constexpr int kFitBins = 1 << kFitLevels;
static_assert(kFitBins <= kMaxBins);

// The axes (bit 0 x, 1 y, 2 z) a space split halves: those at least half
// as wide as the widest, so that cells stay within a factor of two of a
// cube. Halving all three of a cell far from a cube made ever thinner
// slices of its short axis: under a region 10^308 wide and 3 high, the
// cells at depth 24 were 2^-24 of the height, and a ray rising through
// the height crossed 2^24 of them (tests/scenes/fuzz_found/
// flat_cells*.pov: minutes and gigabytes for an 8 by 8 frame). Octree
// builders that do not start from a cube split adaptively the same way.
inline int split_axes(const Box4& region) {
    double width[3], widest = 0.0;
    for (int a = 0; a < 3; ++a) {
        width[a] = region.hi[a] - region.lo[a];
        widest = std::max(widest, width[a]);
    }
    int axes = 0;
    for (int a = 0; a < 3; ++a)
        if (!(width[a] < 0.5 * widest)) axes |= 1 << a;  // (a NaN width splits)
    return axes;
}

// Child o of a space split: its bits pick the upper half along each axis
// the split halves (split_axes); an o with a bit set along an axis it does
// not halve is empty (the child spans that axis whole at bit 0).
inline Box4 octant(const Box4& region, int o) {
    const int axes = split_axes(region);
    if (o & ~axes) return Box4::empty();
    Box4 c = region.child(o);
    for (int a = 0; a < 3; ++a)
        if (!(axes & (1 << a))) {
            c.lo[a] = region.lo[a];
            c.hi[a] = region.hi[a];
        }
    c.lo.w = region.lo.w;
    c.hi.w = region.hi.w;
    return c;
}

// A child of a node under construction: what it refers to, and boxes of
// its contents over bins of the node's time (for its bound).
struct Child {
    NodeRef ref;
    TimeBins bins;
};

inline void fill_empty(float* lo, float* hi, int i) {
    lo[i] = std::numeric_limits<float>::infinity();
    hi[i] = -std::numeric_limits<float>::infinity();
}

// An object of a leaf being grouped: its bound at the start and the end
// of the leaf's time (what the surface-area heuristic prices and sorts
// by), and where the leaf keeps its objects' bins, its place among them
// (the items are reordered, the bins are not).
struct LeafItem {
    LinearExtent extent;
    std::uint32_t object;
    std::uint32_t kept;
};

// An object's bins packed (packed_bins.hpp) in the box over them.
struct KeptBins {
    BinBox box;
    PackedBins bins;
};

}  // namespace hierarchy_build

// A cell's time. In spacetime mode the root's time is the sweeps' own and
// every cell's is a dyadic piece of it (`level`, `index`), cut with the
// same arithmetic as the sweeps' pieces (runtime::dyadic_time), so that an
// object's box over a cell's time is an exact union of its cached pieces.
// The baseline's frames are not dyadic pieces of the animation: level -1,
// and the sweeps answer for any interval.
struct Hierarchy::CellTime {
    using Interval = runtime::Interval;
    Interval t;
    int level = -1;
    std::uint64_t index = 0;

    // Piece p of 2^k equal pieces of this time.
    CellTime part(int k, std::uint64_t p, const Interval& whole) const {
        if (k == 0) return *this;
        CellTime c;
        const std::uint64_t n = std::uint64_t(1) << k;
        if (level >= 0) {
            c.level = level + k;
            c.index = (index << k) + p;
            c.t = Interval(runtime::dyadic_time(whole, c.level, c.index),
                           runtime::dyadic_time(whole, c.level, c.index + 1));
        } else {
            const double lo = p == 0 ? t.lo : t.lo + (t.hi - t.lo) * (double(p) / double(n));
            const double hi =
                p + 1 == n ? t.hi : t.lo + (t.hi - t.lo) * (double(p + 1) / double(n));
            c.t = Interval(lo, hi);
        }
        return c;
    }
};

class Hierarchy::Builder {
  public:
    using Box4 = runtime::Box4;
    using Interval = runtime::Interval;
    using Child = hierarchy_build::Child;
    using LeafItem = hierarchy_build::LeafItem;
    using KeptBins = hierarchy_build::KeptBins;

    Builder(const Hierarchy& h) : h_(h), objects_(h.objects_), options_(h.options_) {}

    // The node of the cell `region` (whose time is `time`) holding
    // `objects` (each meets it). cell_split.cpp.
    NodeRef build(NodeArena& arena, const Box4& region, const CellTime& time,
                  const ObjectList& list, int depth, Counters& counters) const;

  private:
    bool space_only() const { return options_.split == SplitMode::Space; }

    // Bounds are fitted to this many bins of a node's time (one for the
    // baseline, whose bounds are boxes over a frame's shutter).
    int fit_levels() const { return space_only() ? 0 : hierarchy_build::kFitLevels; }

    // Object i's box over a piece of time, clipped to the region.
    Box4 object_over(std::uint32_t i, const CellTime& piece, const Box4& region) const {
        const runtime::TimeSweep& sweep = objects_.sweeps[i];
        const Box4 box = piece.level >= 0 ? sweep.box_over_dyadic(piece.level, piece.index)
                                          : sweep.box_over(piece.t);
        return box.intersection(region);
    }

    // Object i over 2^k equal pieces of the cell's time, clipped to the
    // region, into out[0 .. 2^k): looked up in its sweep, or refined by the
    // object where the pieces are finer than the sweep's
    // (TimeSweep::boxes_over_dyadic). With edge_lo and edge_hi (2^k + 1
    // each), also the edges of its lines where the sweep has them (not
    // clipped): returns whether it had.
    bool object_pieces(std::uint32_t i, const Box4& region, const CellTime& time, int k, Box4* out,
                       glm::dvec3* edge_lo = nullptr, glm::dvec3* edge_hi = nullptr) const {
        const std::size_t n = std::size_t(1) << k;
        if (time.level >= 0) {
            const bool lined = objects_.sweeps[i].boxes_over_dyadic(
                time.level + k, time.index << k, n, *objects_.objects[i], out, edge_lo, edge_hi);
            for (std::size_t p = 0; p < n; ++p) out[p] = out[p].intersection(region);
            return lined;
        }
        for (std::size_t p = 0; p < n; ++p)
            out[p] = object_over(i, time.part(k, p, objects_.time), region);
        return false;
    }

    // Object i over 2^k equal pieces of the cell's time, clipped to it,
    // with its lines where it has them (TimeBins).
    TimeBins object_bins(std::uint32_t i, const Box4& region, const CellTime& time, int k) const {
        std::array<Box4, kMaxBins> pieces;
        std::array<glm::dvec3, kMaxBins + 1> lo, hi;
        const bool lined = object_pieces(i, region, time, k, pieces.data(), lo.data(), hi.data());
        TimeBins bins = TimeBins::empty(1 << k);
        for (int p = 0; p < bins.count; ++p) bins.bin[p] = BinBox::of(pieces[p]);
        bins.lined = lined && !bins.is_empty();
        if (!bins.lined) return bins;
        for (int j = 0; j <= bins.count; ++j) bins.edge[j] = BinBox::of(lo[j], hi[j]);
        return bins.clipped(region);
    }

    // Cell splitting (cell_split.cpp).
    Split choose(const Box4& region, const CellTime& time,
                 const std::vector<std::uint32_t>& objects, int depth, Counters& counters) const;
    static ObjectList shared_list(const ObjectList& parent, std::vector<std::uint32_t> part);
    NodeRef child_cell(NodeArena& arena, const Box4& region, const CellTime& time,
                       ObjectList objects, int depth, Counters& counters) const;
    NodeRef time_node(NodeArena& arena, const Box4& region, const CellTime& time,
                      const ObjectList& list, int depth, Split split, Counters& counters) const;
    NodeRef space_node(NodeArena& arena, const Box4& region, const CellTime& time,
                       const ObjectList& list, int depth, Counters& counters) const;

    // The price of a split (cell_cost.cpp).
    static void scale_object_sums(CostSummary& s, double factor);
    CostSummary cost_summary(const Box4& region, const CellTime& time,
                             const std::vector<std::uint32_t>& objects) const;
    int time_levels(const CellTime& time, const std::vector<std::uint32_t>& objects) const;

    // The leaf's own hierarchy (leaf_hierarchy.cpp): what the grouping of
    // one leaf shares, the leaf, and a node over a run of its items.
    struct Leaf {
        NodeArena& arena;
        const Box4& region;
        const CellTime& time;
        int k;                              // fit_levels()
        const std::vector<KeptBins>* kept;  // null: bins made again at the bottom
    };
    NodeRef leaf(NodeArena& arena, const Box4& region, const CellTime& time,
                 const std::vector<std::uint32_t>& objects, Counters& counters) const;
    Child group_range(const Leaf& leaf, std::vector<LeafItem>& items, std::size_t begin,
                      std::size_t end, Counters& counters, bool top = false) const;
    LinearExtent placed_ends(std::uint32_t i, const Box4& region, const CellTime& time) const;

    // Nodes over children's bounds (node_fit.cpp).
    NodeRef bound_node(NodeArena& arena, const Interval& time, const std::vector<Child>& children,
                       Counters& counters) const;
    static bool moves_within(const std::vector<Child>& children);
    NodeRef box_node(NodeArena& arena, const Interval& time,
                     const std::vector<Child>& children) const;
    NodeRef motion_node(NodeArena& arena, const Interval& time, const std::vector<Child>& children,
                        const std::vector<LinearBox>& fits) const;
    NodeRef slab_node(NodeArena& arena, const Interval& time,
                      const std::vector<Child>& children) const;
    // A leaf's bottom node over objects, and its piecewise-linear style
    // (node_piece.cpp).
    NodeRef object_node(NodeArena& arena, const Interval& time, const std::vector<Child>& children,
                        Counters& counters) const;
    NodeRef piece_node(NodeArena& arena, const Interval& time,
                       const std::vector<Child>& children) const;
    bool pieces_pay(const std::vector<Child>& children) const;

    const Hierarchy& h_;
    const SweptObjects& objects_;
    const BuildOptions& options_;
};

}  // namespace hexant::tracer
