#include "tracer/hierarchy.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include <tbb/parallel_for.h>

#include "runtime/slab_bound.hpp"
#include "runtime/work_counts.hpp"
#include "tracer/bound_rounding.hpp"
#include "tracer/linear_bound.hpp"
#include "tracer/packed_bins.hpp"
#include "tracer/split_criterion.hpp"

namespace hexant::tracer {

using runtime::Box4;
using runtime::Interval;

Criterion parse_criterion(const std::string& name) {
    if (name == "cost") return Criterion::Cost;
    if (name == "paper") return Criterion::Paper;
    throw std::invalid_argument("unknown split criterion '" + name + "' (cost or paper)");
}

BuildKind parse_build_kind(const std::string& name) {
    if (name == "lazy") return BuildKind::Lazy;
    if (name == "eager") return BuildKind::Eager;
    throw std::invalid_argument("unknown build '" + name + "' (lazy or eager)");
}

BoundStyle parse_bound_style(const std::string& name) {
    if (name == "auto") return BoundStyle::Auto;
    if (name == "box") return BoundStyle::Box;
    if (name == "linear") return BoundStyle::Linear;
    if (name == "slabs") return BoundStyle::Slabs;
    throw std::invalid_argument("unknown bound style '" + name + "' (auto, box, linear or slabs)");
}

SweptObjects SweptObjects::of(std::span<const runtime::IntelligentObject* const> objects,
                              const Box4& scene, const BuildOptions& options) {
    SweptObjects set;
    set.objects.assign(objects.begin(), objects.end());
    const Interval time = scene.time();
    set.time = time;
    runtime::SweepPricing pricing;
    pricing.object_cost = options.moving_object_cost;  // only moving objects are cut
    // The rays spread over the objects' own extent (a camera looks at
    // them), not over the eye and lights the root also holds.
    Box4 extent = Box4::empty();
    for (const auto* o : objects) extent.extend(o->box_over(time).intersection(scene));
    const double area = surface_area(extent);
    if (options.rays_per_frame > 0.0 && options.frame_interval > 0.0 && area > 0.0 &&
        std::isfinite(area) && options.build_cost > 0.0)
        pricing.ray_density = options.rays_per_frame / options.frame_interval / area;
    std::size_t moving = 0;
    for (const auto* o : objects) moving += o->moves() ? 1 : 0;
    int depth = kMaxSweepDepth;
    while (depth > 0 && moving * (std::size_t(1) << depth) > kSweepPieceBudget) --depth;
    set.sweeps.resize(objects.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, objects.size(), 64),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t i = r.begin(); i < r.end(); ++i)
                              set.sweeps[i] =
                                  runtime::TimeSweep::of(*objects[i], time, depth, pricing);
                      });
    return set;
}

std::size_t SweptObjects::bytes() const {
    std::size_t total = objects.capacity() * sizeof(void*);
    for (const auto& s : sweeps) total += s.bytes();
    return total;
}

namespace {

// Work on fewer objects than this stays on one thread.
constexpr std::size_t kParallelGrain = 1024;

// The cost criterion prices a cell of more objects than this from an even
// sample of this many (every (n / kCostSample)-th, the same in every run):
// its sums of the objects' areas and counts scaled up by n / kCostSample,
// the boxes over everything (the cell's, its halves' and octants') the
// sample's union. A price is an estimate anyway (large-BVH builders bin a
// sample likewise); pricing every object of a slab of 10^5 moving spheres
// cost more than building its nodes (swarm, 4 frames of 16: 20 s of the
// render's 25 were cells built, half of it this pass over 10^5 objects at up
// to 2^7 pieces of time each). The choice changes which cells are built,
// never an answer (tests/tracer: lazy and eager, both criteria, same images).
constexpr std::size_t kCostSample = 4096;

// Bounds are fitted to this many equal pieces (bins) of a node's time.
constexpr int kFitLevels = 3;
constexpr int kFitBins = 1 << kFitLevels;
static_assert(kFitBins <= kMaxBins);

// The axes (bit 0 x, 1 y, 2 z) a space split halves: those at least half
// as wide as the widest, so that cells stay within a factor of two of a
// cube. Halving all three of a cell far from a cube made ever thinner
// slices of its short axis: under a region 10^308 wide and 3 high, the
// cells at depth 24 were 2^-24 of the height, and a ray rising through
// the height crossed 2^24 of them (tests/scenes/fuzz_found/
// flat_cells*.pov: minutes and gigabytes for an 8 by 8 frame). Octree
// builders that do not start from a cube split adaptively the same way.
int split_axes(const Box4& region) {
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
Box4 octant(const Box4& region, int o) {
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

void fill_empty(float* lo, float* hi, int i) {
    lo[i] = std::numeric_limits<float>::infinity();
    hi[i] = -std::numeric_limits<float>::infinity();
}

}  // namespace

// A cell's time. In spacetime mode the root's time is the sweeps' own and
// every cell's is a dyadic piece of it (`level`, `index`), cut with the
// same arithmetic as the sweeps' pieces (runtime::dyadic_time), so that an
// object's box over a cell's time is an exact union of its cached pieces.
// The baseline's frames are not dyadic pieces of the animation: level -1,
// and the sweeps answer for any interval.
struct Hierarchy::CellTime {
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
            const double hi = p + 1 == n ? t.hi : t.lo + (t.hi - t.lo) * (double(p + 1) / double(n));
            c.t = Interval(lo, hi);
        }
        return c;
    }
};

class Hierarchy::Builder {
public:
    Builder(const Hierarchy& h) : h_(h), objects_(h.objects_), options_(h.options_) {}

    // The node of the cell `region` (whose time is `time`) holding
    // `objects` (each meets it).
    NodeRef build(NodeArena& arena, const Box4& region, const CellTime& time, const ObjectList& list,
                  int depth, Counters& counters) const {
        ++counters.cells;
        arena.count_cell();
        const std::vector<std::uint32_t>& objects = *list;
        if (objects.empty()) return {};
        const Split split =
            depth < options_.depth_limit() ? choose(region, time, objects, depth, counters) : Split::Leaf;
        switch (split) {
            case Split::Leaf: return leaf(arena, region, time, objects, counters);
            case Split::Space: return space_node(arena, region, time, list, depth, counters);
            case Split::Time:
            case Split::Both: return time_node(arena, region, time, list, depth, split, counters);
        }
        return {};
    }

private:
    bool space_only() const { return options_.split == SplitMode::Space; }

    // Bounds are fitted to this many bins of a node's time (one for the
    // baseline, whose bounds are boxes over a frame's shutter).
    int fit_levels() const { return space_only() ? 0 : kFitLevels; }

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
    // (TimeSweep::boxes_over_dyadic).
    void object_pieces(std::uint32_t i, const Box4& region, const CellTime& time, int k,
                       Box4* out) const {
        const std::size_t n = std::size_t(1) << k;
        if (time.level >= 0) {
            objects_.sweeps[i].boxes_over_dyadic(time.level + k, time.index << k, n,
                                                 *objects_.objects[i], out);
            for (std::size_t p = 0; p < n; ++p) out[p] = out[p].intersection(region);
            return;
        }
        for (std::size_t p = 0; p < n; ++p)
            out[p] = object_over(i, time.part(k, p, objects_.time), region);
    }

    // Object i over 2^k equal pieces of the cell's time, clipped to it.
    TimeBins object_bins(std::uint32_t i, const Box4& region, const CellTime& time, int k) const {
        std::array<Box4, kMaxBins> pieces;
        object_pieces(i, region, time, k, pieces.data());
        TimeBins bins = TimeBins::empty(1 << k);
        for (int p = 0; p < bins.count; ++p) bins.bin[p] = BinBox::of(pieces[p]);
        return bins;
    }

    Split choose(const Box4& region, const CellTime& time, const std::vector<std::uint32_t>& objects,
                 int depth, Counters& counters) const {
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
            if (options_.shutter_time > 0.0) frames = std::max(frames, std::min(1.0, w / options_.shutter_time));
            else frames = std::max(frames, 1.0);
            prices.rays = options_.rays_per_frame * frames * summary.cell / h_.root_area_;
        }
        return cost_split(summary, prices, space_only());
    }

    // A sample's sums of object areas and counts, as the whole cell's.
    static void scale_object_sums(CostSummary& s, double factor) {
        const auto count = [&](std::size_t c) {
            return std::min(s.objects, std::size_t(std::llround(double(c) * factor)));
        };
        for (double& a : s.time_objects) a *= factor;
        s.object_cell *= factor;
        for (double& a : s.object_half) a *= factor;
        for (double& a : s.object_octant) a *= factor;
        for (auto& halves : s.object_octant_half)
            for (double& a : halves) a *= factor;
        for (std::size_t& c : s.count_half) c = count(c);
        for (std::size_t& c : s.count_octant) c = count(c);
        for (auto& halves : s.count_octant_half)
            for (std::size_t& c : halves) c = count(c);
    }

    // One pass over the cell's objects (or kCostSample of them): each
    // object's sweep over 2^L equal
    // pieces of the cell's time, clipped to the cell, merged pairwise up to
    // the whole time; the halves and quarters also clipped to the octants.
    // Where the cell's bounds may be linear-motion boxes, an object's bound
    // over the cell's whole time (for a leaf, or an octant) is priced at
    // its fitted box's area, not its halves' boxes. (The frame-by-frame
    // baseline's cells have one piece of time: every level is that piece.)
    CostSummary cost_summary(const Box4& region, const CellTime& time,
                             const std::vector<std::uint32_t>& objects) const {
        CostSummary s;
        s.objects = objects.size();
        const int levels = space_only() ? 0 : time_levels(time, objects);
        s.time_levels = levels;
        const auto level = [&](int k) { return std::min(k, levels); };
        const int halves = level(1), quarters = level(2), fits = level(kFitLevels);
        // (Only where the sweeps resolve the cell's time into its bins: a
        // line fitted to one or two pieces is no tighter than their boxes.)
        const bool linear = !space_only() && levels >= kFitLevels &&
                            (options_.bounds == BoundStyle::Auto ||
                             options_.bounds == BoundStyle::Linear);
        std::array<Box4, 8> octants;
        for (int o = 0; o < 8; ++o) octants[o] = octant(region, o);
        // The union of everything per piece, at every level.
        std::vector<std::vector<Box4>> cell(levels + 1);
        for (int k = 0; k <= levels; ++k) cell[k].assign(std::size_t(1) << k, Box4::empty());
        std::array<std::vector<Box4>, 8> octant_halves, octant_quarters;
        for (int o = 0; o < 8; ++o) {
            octant_halves[o].assign(std::size_t(1) << halves, Box4::empty());
            octant_quarters[o].assign(std::size_t(1) << quarters, Box4::empty());
        }
        std::vector<Box4> pieces;
        const std::size_t n_objects = objects.size();
        const std::size_t sampled = std::min(n_objects, kCostSample);
        for (std::size_t j = 0; j < sampled; ++j) {
            const std::uint32_t i =
                sampled == n_objects ? objects[j] : objects[j * n_objects / sampled];
            // A moving object's test costs more (its placement at the ray's
            // time): its areas weigh more, relative to a still object's.
            const double weight =
                objects_.objects[i]->moves() ? options_.moving_object_cost / options_.object_cost : 1.0;
            const std::size_t n = std::size_t(1) << levels;
            pieces.resize(n);
            object_pieces(i, region, time, levels, pieces.data());
            // How much tighter than its halves' boxes a fitted linear-motion
            // box holds this object over the whole cell time.
            double fit_share = 1.0;
            double halves_area = 0.0;
            bool in_half[2] = {false, false}, in_octant[8] = {}, in_octant_half[8][2] = {};
            for (int k = levels; k >= 0; --k) {
                const std::size_t count = std::size_t(1) << k;
                const double share = 1.0 / double(count);
                double level_area = 0.0;
                for (std::size_t p = 0; p < count; ++p) {
                    level_area += surface_area(pieces[p]) * share * weight;
                    cell[k][p].extend(pieces[p]);
                }
                s.time_objects[k] += level_area;
                if (k == fits && linear && fits > 0) {
                    TimeBins bins;
                    bins.count = int(count);
                    for (std::size_t p = 0; p < count; ++p) bins.bin[p] = BinBox::of(pieces[p]);
                    fit_share = fit_linear(bins).mean_area() * weight;
                }
                if (k == halves) {
                    halves_area = level_area;
                    if (linear && fits > 0 && halves_area > 0.0)
                        fit_share = std::clamp(fit_share / halves_area, 0.0, 1.0);
                    else
                        fit_share = 1.0;
                    s.object_cell += level_area * fit_share;
                }
                if (k == halves || k == quarters) {
                    for (std::size_t p = 0; p < count; ++p) {
                        if (pieces[p].is_empty()) continue;
                        for (int o = 0; o < 8; ++o) {
                            const Box4 part = pieces[p].intersection(octants[o]);
                            if (part.is_empty()) continue;
                            const double area = surface_area(part) * share * weight;
                            if (k == halves) {
                                s.object_octant[o] += area * fit_share;
                                octant_halves[o][p].extend(part);
                                in_octant[o] = true;
                            }
                            if (k == quarters) {
                                s.object_octant_half[o][p * 2 / count] += area;
                                octant_quarters[o][p].extend(part);
                                in_octant_half[o][p * 2 / count] = true;
                            }
                        }
                    }
                }
                if (k == quarters)
                    for (std::size_t p = 0; p < count; ++p) {
                        s.object_half[p * 2 / count] += surface_area(pieces[p]) * share * weight;
                        if (!pieces[p].is_empty()) in_half[p * 2 / count] = true;
                    }
                // Up a level: the union of each pair.
                for (std::size_t p = 0; 2 * p + 1 < count; ++p) {
                    Box4 merged = pieces[2 * p];
                    merged.extend(pieces[2 * p + 1]);
                    pieces[p] = merged;
                }
            }
            for (int h = 0; h < 2; ++h) {
                s.count_half[h] += in_half[h];
                for (int o = 0; o < 8; ++o) s.count_octant_half[o][h] += in_octant_half[o][h];
            }
            for (int o = 0; o < 8; ++o) s.count_octant[o] += in_octant[o];
        }
        if (sampled < n_objects) scale_object_sums(s, double(n_objects) / double(sampled));
        for (int k = 0; k <= levels; ++k) {
            const double share = 1.0 / double(cell[k].size());
            for (const Box4& b : cell[k]) s.time_cell[k] += surface_area(b) * share;
        }
        s.cell = s.time_cell[halves];
        {
            const double share = 1.0 / double(cell[quarters].size());
            for (std::size_t p = 0; p < cell[quarters].size(); ++p)
                s.half[p * 2 / cell[quarters].size()] += surface_area(cell[quarters][p]) * share;
        }
        for (int o = 0; o < 8; ++o) {
            const double hs = 1.0 / double(octant_halves[o].size());
            for (const Box4& b : octant_halves[o]) s.octant[o] += surface_area(b) * hs;
            const double qs = 1.0 / double(octant_quarters[o].size());
            for (std::size_t p = 0; p < octant_quarters[o].size(); ++p)
                s.octant_half[o][p * 2 / octant_quarters[o].size()] +=
                    surface_area(octant_quarters[o][p]) * qs;
        }
        return s;
    }

    // How many halvings of the cell's time the cost criterion looks at:
    // down to the finest pieces its objects' sweeps keep (finer ones repeat
    // them), at least to quarters, at most CostSummary::kMaxTimeLevels; none
    // for a cell no longer than those pieces (its halves' boxes would be
    // its own).
    //
    // A cell inside one piece of the sweeps looks at eighths of its time
    // when some of its objects' sweeps refine (chords: finer pieces are
    // new answers, at a placement per end), down to 1/64 of a piece.
    int time_levels(const CellTime& time, const std::vector<std::uint32_t>& objects) const {
        const double span = time.t.width();
        double finest = span;
        bool refine = false;
        for (const std::uint32_t i : objects) {
            const auto& sweep = objects_.sweeps[i];
            const double piece = sweep.time().width() / double(sweep.piece_count());
            finest = std::min(finest, piece);
            if (sweep.refines() && span <= piece && span > piece / 64.0) refine = true;
        }
        if (!(span > finest)) return refine && time.level >= 0 ? kFitLevels : 0;
        int levels = 2;
        while (levels < CostSummary::kMaxTimeLevels && finest > 0.0 &&
               span / double(std::size_t(1) << levels) > finest)
            ++levels;
        return levels;
    }

    // A child cell: built now (eager) or when a ray first reaches it.
    // A child's list: the parent's own where it holds all of the parent's
    // objects (a part of a list holds them in the same order).
    static ObjectList shared_list(const ObjectList& parent, std::vector<std::uint32_t> part) {
        if (part.size() == parent->size()) return parent;
        return std::make_shared<const std::vector<std::uint32_t>>(std::move(part));
    }

    NodeRef child_cell(NodeArena& arena, const Box4& region, const CellTime& time, ObjectList objects,
                       int depth, Counters& counters) const {
        if (options_.build == BuildKind::Eager) return build(arena, region, time, objects, depth, counters);
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
    NodeRef time_node(NodeArena& arena, const Box4& region, const CellTime& time, const ObjectList& list,
                      int depth, Split split, Counters& counters) const {
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
    NodeRef space_node(NodeArena& arena, const Box4& region, const CellTime& time, const ObjectList& list,
                       int depth, Counters& counters) const {
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
                bool meets = false;
                for (int b = 0; b < mine.count; ++b) {
                    const BinBox part = mine.bin[b].clipped(octants[o]);
                    if (part.is_empty()) continue;
                    bins[o].bin[b].extend(part);
                    meets = true;
                }
                if (meets) lists[o].push_back(i);
            }
        }
        std::vector<int> used;
        for (int o = 0; o < 8; ++o)
            if (!lists[o].empty()) used.push_back(o);
        std::vector<Child> children(used.size());
        const auto make = [&](std::size_t c, Counters& counts) {
            const int o = used[c];
            children[c].ref =
                child_cell(arena, octants[o], time, shared_list(list, std::move(lists[o])), depth + 1, counts);
            children[c].bins = bins[o];
        };
        if (options_.build == BuildKind::Eager && used.size() > 1) {
            tbb::enumerable_thread_specific<Counters> each;
            tbb::parallel_for(std::size_t(0), used.size(), [&](std::size_t c) { make(c, each.local()); });
            for (const Counters& c : each) counters += c;
        } else {
            for (std::size_t c = 0; c < used.size(); ++c) make(c, counters);
        }
        // A lone child needs no node: the bound that led here holds it.
        if (children.size() == 1) return children.front().ref;
        return bound_node(arena, time.t, children, counters);
    }

    // A cell at the bottom: its objects as children, each bounded inside it.
    // While it is built a leaf of n objects holds n items of 128 bytes,
    // each object's bins packed beside its box (packed_bins.hpp); it held
    // 304 bytes an object (the bins in floats, and a 96-byte item), 30 MB
    // for a leaf of 10^5 objects, and the two threads build two at once.
    NodeRef leaf(NodeArena& arena, const Box4& region, const CellTime& time,
                 const std::vector<std::uint32_t>& objects, Counters& counters) const {
        const int k = fit_levels();
        std::vector<Item> items(objects.size());
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, objects.size(), kParallelGrain),
                          [&](const tbb::blocked_range<std::size_t>& r) {
                              for (std::size_t i = r.begin(); i < r.end(); ++i) {
                                  const TimeBins bins = object_bins(objects[i], region, time, k);
                                  const BinBox hull = bins.hull();
                                  items[i].box = hull;
                                  items[i].object = objects[i];
                                  items[i].bins = PackedBins::pack(bins, hull);
                              }
                          });
        // Objects the cell's bins miss (in place: no second copy of a large leaf).
        std::erase_if(items, [](const Item& item) { return item.box.is_empty(); });
        if (items.empty()) return {};
        counters.object_refs += items.size();
        const Leaf leaf{arena, region, time, k};
        return group_range(leaf, items, 0, items.size(), counters, true).ref;
    }

    // An object of a leaf being grouped: the box over its bins (for the
    // surface-area heuristic, and the frame its bins are packed in), and its
    // bins.
    struct Item {
        BinBox box;
        std::uint32_t object;
        PackedBins bins;
    };
    // The centre of an item's box along `axis`, where the cuts sort it.
    // Never NaN: a box unbounded both ways ([-inf, inf]) has centre 0, so
    // that the cuts' order is a strict weak one and a bin index is never a
    // NaN cast to int (fuzz_found/unbounded_centre.pov, UBSan).
    static float centre(const Item& item, int axis) {
        const float c = 0.5f * item.box.lo[axis] + 0.5f * item.box.hi[axis];
        return c == c ? c : 0.0f;
    }
    // Where the centres of [first, last) spread widest: the axis, and the
    // spread's low end and width along it.
    struct Spread {
        int axis;
        double lo, width;
    };
    template <class It>
    static Spread centre_spread(It first, It last) {
        glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
        for (It i = first; i != last; ++i)
            for (int a = 0; a < 3; ++a) {
                lo[a] = std::min(lo[a], double(centre(*i, a)));
                hi[a] = std::max(hi[a], double(centre(*i, a)));
            }
        const glm::dvec3 e = hi - lo;
        const int axis = e.x >= e.y && e.x >= e.z ? 0 : e.y >= e.z ? 1 : 2;
        return {axis, lo[axis], e[axis]};
    }
    // Orders items by their centres along `axis`.
    static auto by_centre(int axis) {
        return [axis](const Item& a, const Item& b) { return centre(a, axis) < centre(b, axis); };
    }
    // What the grouping of one leaf shares.
    struct Leaf {
        NodeArena& arena;
        const Box4& region;
        const CellTime& time;
        int k;  // fit_levels()
    };

    // More objects than a node holds: a small bounding volume hierarchy
    // over them, eight-wide. The cluster with the largest area times count
    // is cut in two where the surface-area heuristic says (sixteen bins of
    // box centres along their widest spread, as binned SAH builders do),
    // until there are eight or none holds more than a node does; each
    // cluster of several becomes a node below. (Cutting on to eight
    // clusters filled the lowest nodes with three objects on average: 31,000
    // nodes for a leaf of 10^5 objects.) Returns the node over items
    // [begin, end) with the bins of everything in it, its objects' bins
    // unpacked at the bottom; the items are reordered in place. A
    // lone object below the leaf's top is its parent's child itself.
    Child group_range(const Leaf& leaf, std::vector<Item>& items, std::size_t begin, std::size_t end,
                      Counters& counters, bool top = false) const {
        const Interval& time = leaf.time.t;
        if (end - begin <= std::size_t(kNodeWidth)) {
            std::vector<Child> members;
            members.reserve(end - begin);
            Child merged{{}, TimeBins::empty(1 << leaf.k)};
            for (std::size_t i = begin; i < end; ++i) {
                members.push_back({NodeRef::object(items[i].object), items[i].bins.unpack(items[i].box)});
                merged.bins.add(members.back().bins);
            }
            if (members.size() == 1 && !top) return members.front();
            merged.ref = bound_node(leaf.arena, time, members, counters);
            return merged;
        }
        struct Cluster {
            std::size_t begin, end;  // in items
            double weight;           // area times count: what splitting it may save
        };
        const auto weigh = [&](std::size_t b, std::size_t e) {
            BinBox box;
            for (std::size_t i = b; i < e; ++i) box.extend(items[i].box);
            return Cluster{b, e, surface_area(box) * double(e - b)};
        };
        std::vector<Cluster> clusters;
        const std::size_t n = end - begin;
        if (n <= std::size_t(kNodeWidth * kNodeWidth)) {
            // The last level above the objects: as few nodes as hold them,
            // runs of the centres in order along their widest spread (binary
            // cuts left the lowest nodes 60% full: 23,000 nodes for a leaf of
            // 10^5 objects where 14,300 hold them).
            std::sort(items.begin() + begin, items.begin() + end,
                      by_centre(centre_spread(items.begin() + begin, items.begin() + end).axis));
            const std::size_t runs = (n + kNodeWidth - 1) / kNodeWidth;
            for (std::size_t r = 0; r < runs; ++r)
                clusters.push_back({begin + n * r / runs, begin + n * (r + 1) / runs, 0.0});
        } else {
            clusters.push_back(weigh(begin, end));
        }
        while (clusters.size() < std::size_t(kNodeWidth) && n > std::size_t(kNodeWidth * kNodeWidth)) {
            std::size_t pick = clusters.size();
            for (std::size_t c = 0; c < clusters.size(); ++c)
                if (clusters[c].end - clusters[c].begin > std::size_t(kNodeWidth) &&
                    (pick == clusters.size() || clusters[c].weight > clusters[pick].weight))
                    pick = c;
            if (pick == clusters.size()) break;
            const Cluster c = clusters[pick];
            const std::size_t middle = sah_cut(items.begin() + c.begin, items.begin() + c.end) + c.begin;
            clusters[pick] = weigh(c.begin, middle);
            clusters.push_back(weigh(middle, c.end));
        }
        // The clusters' nodes, built side by side where they are large (they
        // own disjoint runs of the items).
        std::vector<Child> grouped(clusters.size());
        std::vector<Counters> each(clusters.size());
        const auto make = [&](std::size_t n) {
            grouped[n] = group_range(leaf, items, clusters[n].begin, clusters[n].end, each[n]);
        };
        if (end - begin >= kParallelGrain)
            tbb::parallel_for(std::size_t(0), clusters.size(), make);
        else
            for (std::size_t n = 0; n < clusters.size(); ++n) make(n);
        for (const Counters& c : each) counters += c;
        Child merged{{}, TimeBins::empty(1 << leaf.k)};
        for (const Child& c : grouped) merged.bins.add(c.bins);
        merged.ref = bound_node(leaf.arena, time, grouped, counters);
        return merged;
    }

    // Reorders [first, last) (items) into two runs
    // and returns the length of the first: the cut with the least
    // area-times-count over sixteen bins of the centres along their widest
    // spread; the median when the centres coincide or no cut helps.
    template <class It>
    static std::size_t sah_cut(It first, It last) {
        const std::size_t n = std::size_t(last - first);
        // (Named, not a structured binding: clang before 16 cannot capture one.)
        const Spread spread = centre_spread(first, last);
        const int axis = spread.axis;
        const double lo = spread.lo, width = spread.width;
        const auto median = [&] {
            std::nth_element(first, first + n / 2, last, by_centre(axis));
            return n / 2;
        };
        if (!(width > 0.0) || !std::isfinite(width)) return median();
        constexpr int kBins = 16;
        std::array<BinBox, kBins> box;
        std::array<std::size_t, kBins> count{};
        const auto bin_of = [&](const auto& item) {
            return std::clamp(int((centre(item, axis) - lo) / width * kBins), 0, kBins - 1);
        };
        for (It i = first; i != last; ++i) {
            const int b = bin_of(*i);
            box[b].extend(i->box);
            ++count[b];
        }
        // Areas of everything left of each cut, then right of it.
        std::array<double, kBins> left_cost{};
        BinBox acc;
        std::size_t acc_count = 0;
        for (int b = 0; b < kBins - 1; ++b) {
            acc.extend(box[b]);
            acc_count += count[b];
            left_cost[b] = surface_area(acc) * double(acc_count);
        }
        acc = BinBox{};
        acc_count = 0;
        int best = -1;
        double best_cost = std::numeric_limits<double>::infinity();
        for (int b = kBins - 1; b > 0; --b) {
            acc.extend(box[b]);
            acc_count += count[b];
            const double cost = left_cost[b - 1] + surface_area(acc) * double(acc_count);
            if (acc_count < n && acc_count > 0 && cost < best_cost) {
                best_cost = cost;
                best = b;
            }
        }
        if (best < 0) return median();
        const It middle = std::partition(first, last, [&](const auto& item) { return bin_of(item) < best; });
        const std::size_t left = std::size_t(middle - first);
        return left == 0 || left == n ? median() : left;
    }

    // One node over `time` holding the children's bounds, in the style the
    // options ask for (Auto: a linear-motion box where it saves area).
    NodeRef bound_node(NodeArena& arena, const Interval& time, const std::vector<Child>& children,
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
            case BoundStyle::Slabs: ++counters.slab_nodes; return slab_node(arena, time, children);
            default: ++counters.box_nodes; return box_node(arena, time, children);
        }
    }

    // Does anything change from bin to bin?
    static bool moves_within(const std::vector<Child>& children) {
        for (const Child& c : children)
            for (int b = 1; b < c.bins.count; ++b)
                if (c.bins.bin[b] != c.bins.bin[0])
                    return true;
        return false;
    }

    NodeRef box_node(NodeArena& arena, const Interval& time, const std::vector<Child>& children) const {
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
    NodeRef motion_node(NodeArena& arena, const Interval& time, const std::vector<Child>& children,
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

    NodeRef slab_node(NodeArena& arena, const Interval& time, const std::vector<Child>& children) const {
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
                const double hi = bin + 1 == n ? time.hi : time.lo + time.width() * (double(bin + 1) / n);
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

    const Hierarchy& h_;
    const SweptObjects& objects_;
    const BuildOptions& options_;
};

Hierarchy::Hierarchy(const SweptObjects& objects, const Box4& root, const BuildOptions& options,
                     Counters& counters)
    : objects_(objects), options_(options), region_(root),
      builder_(std::make_unique<Builder>(*this)) {
    const auto start = std::chrono::steady_clock::now();
    const std::uint64_t maps = runtime::this_thread_work.deformation_maps;
    std::vector<std::uint32_t> all;
    all.reserve(objects.objects.size());
    for (std::uint32_t i = 0; i < objects.objects.size(); ++i)
        if (!objects.sweeps[i].box_over(root.time()).intersection(root).is_empty()) all.push_back(i);
    CellTime time;
    time.t = root.time();
    // Spacetime mode: the root's time is the sweeps', cut the same way.
    if (root.lo.w == objects.time.lo && root.hi.w == objects.time.hi) time.level = 0;
    root_ = builder_->build(arena_, root, time,
                            std::make_shared<const std::vector<std::uint32_t>>(std::move(all)), 0, counters);
    counters.build_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // The root is entered by every ray: never leave it pending.
    Counters first;
    while (root_.kind() == RefKind::Pending) root_ = expand(&root_, root_, first);
    first.build_seconds += first.lazy_build_seconds;
    first.lazy_build_seconds = 0.0;
    counters += first;
    counters.deformation_maps += runtime::this_thread_work.deformation_maps - maps;
}

Hierarchy::~Hierarchy() = default;

NodeRef Hierarchy::expand(NodeRef* slot, NodeRef pending, Counters& counters) const {
    PendingCell* p = pending.as<PendingCell>();
    // One large cell at a time: this one is reserved before its build
    // begins, and while another is reserved, that one is helped first.
    // Every wait is outside any cell's once flag, as when two threads reach
    // one cell (a wait on another flag from inside one deadlocked in
    // oneTBB: the helpers of the outer cell held the arena's only worker).
    struct Reservation {
        const Hierarchy& h;
        bool held = false;
        ~Reservation() {
            if (!held) return;
            h.large_build_.store(nullptr, std::memory_order_release);
            h.large_build_.notify_all();
        }
    } reservation{*this};
    if (p->object_count >= options_.large_build) {
        for (;;) {
            PendingCell* other = nullptr;
            if (large_build_.compare_exchange_strong(other, p, std::memory_order_acq_rel)) {
                reservation.held = true;
                break;
            }
            if (other == p) break;  // reserved by a thread about to build it: help it
            // Under way (or about to be): wait for it, helping. It would be
            // built here only had its build failed and its flag been reset.
            tbb::collaborative_call_once(other->once, [&] { build_pending(other, counters); });
            // Its reservation ends just after its flag: wait for that, not spin.
            large_build_.wait(other, std::memory_order_acquire);
        }
    }
    tbb::collaborative_call_once(p->once, [&] {
        p->slot = slot;
        build_pending(p, counters);
    });
    NodeRef::store(slot, p->built);
    return p->built;
}

void Hierarchy::build_pending(PendingCell* p, Counters& counters) const {
    const auto start = std::chrono::steady_clock::now();
    CellTime time;
    time.t = p->region.time();
    time.level = p->time_level;
    time.index = p->time_index;
    if (p->slab_root) {
        // Its own arena, and its objects kept for a build after a release.
        p->own = std::make_unique<NodeArena>();
        p->built = builder_->build(*p->own, p->region, time, p->objects, p->depth, counters);
        const std::lock_guard<std::mutex> lock(slabs_mutex_);
        live_slabs_.push_back({p->slot, p});
    } else {
        p->built = builder_->build(p->arena ? *p->arena : arena_, p->region, time, p->objects,
                                   p->depth, counters);
        p->objects.reset();
    }
    counters.lazy_build_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void Hierarchy::release(const LiveSlab& slab) const {
    PendingCell* p = slab.cell;
    NodeRef::store(slab.slot, NodeRef::node(RefKind::Pending, p));
    p->built = {};
    p->own.reset();  // its nodes, and the pending cells below it
    // A fresh flag: the next ray to reach it builds it again.
    p->once.~collaborative_once_flag();
    new (&p->once) tbb::collaborative_once_flag();
}

void Hierarchy::release_outside(double t0, double t1) {
    const std::lock_guard<std::mutex> lock(slabs_mutex_);
    peak_bytes_ = std::max(peak_bytes_, held_bytes());
    // A ray at the time a slab ends goes to the later half (traversal_simd.cpp),
    // so a slab ending where [t0, t1] begins is outside it.
    std::erase_if(live_slabs_, [&](const LiveSlab& s) {
        const bool outside = s.cell->region.hi.w <= t0 || s.cell->region.lo.w > t1;
        if (outside) release(s);
        return outside;
    });
}

std::size_t Hierarchy::held_bytes() const {
    std::size_t held = arena_.bytes();
    for (const LiveSlab& s : live_slabs_) held += s.cell->own->bytes();
    return held;
}

std::size_t Hierarchy::bytes() const {
    const std::lock_guard<std::mutex> lock(slabs_mutex_);
    return held_bytes();
}

std::size_t Hierarchy::peak_bytes() const {
    const std::lock_guard<std::mutex> lock(slabs_mutex_);
    return std::max(peak_bytes_, held_bytes());
}

void Hierarchy::count_full(Counters& counters) const {
    Counters extra;
    // Cells in the lasting part, and in each slab counted once, however
    // often a render built it again.
    std::uint64_t slab_cells = 0;
    const auto visit = [&](auto&& self, NodeRef* slot) -> void {
        NodeRef ref = NodeRef::load(slot);
        PendingCell* slab = nullptr;
        if (ref.kind() == RefKind::Pending) {
            if (ref.as<PendingCell>()->slab_root) slab = ref.as<PendingCell>();
            ref = expand(slot, ref, extra);
        }
        switch (ref.kind()) {
            case RefKind::BoxNode:
                for (auto& c : ref.as<BoxNode>()->child) self(self, &c);
                break;
            case RefKind::MotionNode:
                for (auto& c : ref.as<MotionNode>()->child) self(self, &c);
                break;
            case RefKind::SlabNode:
                for (auto& c : ref.as<SlabNode>()->child) self(self, &c);
                break;
            case RefKind::TimeNode:
                for (auto& c : ref.as<TimeNode>()->child) self(self, &c);
                break;
            default:
                break;
        }
        if (slab) {
            // Counted: let it go again, so that counting holds one slab at a time.
            slab_cells += slab->own->cells();
            const std::lock_guard<std::mutex> lock(slabs_mutex_);
            peak_bytes_ = std::max(peak_bytes_, held_bytes());
            std::erase_if(live_slabs_, [&](const LiveSlab& s) {
                if (s.cell != slab) return false;
                release(s);
                return true;
            });
        }
    };
    NodeRef root = root_;
    visit(visit, &root);
    {
        const std::lock_guard<std::mutex> lock(slabs_mutex_);
        for (const LiveSlab& s : live_slabs_) slab_cells += s.cell->own->cells();
    }
    counters.cells_full += arena_.cells() + slab_cells;
}

}  // namespace hexant::tracer
