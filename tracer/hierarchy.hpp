// Glassner's hybrid hierarchy over spacetime: space (and time) subdivision
// down, bounding volumes up (docs/design.md, "The hybrid hierarchy").
//
// Down: a cell (a 4D box) is halved in time, in space (eight octants), in
// both, or not at all, as the split criterion says:
//  - Criterion::Paper, the paper's: more than `max_objects` objects, or more
//    than one filling less than `max_occupancy` of the cell, split it, to
//    `max_depth` (default 5); halving time only where something moves, and a
//    lone moving object's cell halves time alone.
//  - Criterion::Cost: a surface-area heuristic extended to time (Woop, Afra
//    and Benthin's STBVH, HPG 2017): the expected cost of a ray at a random
//    instant meeting the cell, for each of the four choices, from the areas
//    its contents' boxes present over quarters of its time; the cheapest
//    wins (split_criterion.hpp).
// Up: each child's bound is what its contents occupy inside it (their
// cached sweeps clipped to the child), fitted as a box, a linear-motion box
// or a 12-slab bound (cell.hpp). At the bottom a cell's objects are the
// children of a node, each with its own bound inside the cell, so a ray
// tests an object only where it meets that object's own bound.
//
// Lazily, as the paper's future work proposes: with BuildKind::Lazy a cell's
// children are built the first time a ray reaches it (any thread; exactly
// once), so a frame pays only for the cells its rays enter. BuildKind::Eager
// builds everything at once, in parallel.
//
// The frame-by-frame baseline uses the same builder with SplitMode::Space:
// the root's time is one frame's shutter, cells split in space only, and
// every bound is a box over that whole interval, as the paper's baseline.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include <tbb/collaborative_call_once.h>

#include "runtime/bounds/time_sweep.hpp"
#include "runtime/geometry/spacetime.hpp"
#include "runtime/objects/intelligent_object.hpp"
#include "tracer/cell.hpp"
#include "tracer/counters.hpp"
#include "tracer/node_arena.hpp"
#include "tracer/time_index.hpp"

namespace hexant::tracer {

enum class SplitMode { Spacetime, Space };
enum class Criterion { Cost, Paper };
enum class BuildKind { Lazy, Eager };
// Auto: per node, a linear-motion box where it is clearly tighter than a
// box (what it saves in area outweighs its dearer test), else a box.
enum class BoundStyle { Auto, Box, Linear, Slabs };

struct BuildOptions {
    SplitMode split = SplitMode::Spacetime;
    Criterion criterion = Criterion::Cost;
    BuildKind build = BuildKind::Lazy;
    BoundStyle bounds = BoundStyle::Auto;
    // Depth limit; 0 or less: the criterion's own (paper 5, cost 24).
    int max_depth = 0;
    // Unions of many still members under a moving transform built as
    // instances (runtime/objects/instance_object.hpp); off: each member an
    // object of the hierarchy (--no-instances, for comparison).
    bool instances = true;
    // The paper's criterion.
    std::size_t max_objects = 3;
    double max_occupancy = 0.3;
    // The cost criterion's prices, in units of one node test (eight bounds
    // at once, about 10 ns): testing a still object (a sphere, a polygon:
    // about 50 ns), testing a moving one (its placement evaluated at the
    // ray's time first: about 150 ns), and copying an object reference
    // into a split cell (split_criterion.hpp, CostPrices).
    double object_cost = 5.0;
    double moving_object_cost = 15.0;
    double build_cost = 100.0;
    // The rays a frame traces (0: unknown, and splits are free), the time
    // between frames and how long each frame's shutter is open: a cell gets
    // the rays of the shutter time it spans, in its share of the root's area.
    double rays_per_frame = 0.0;
    double frame_interval = 0.0;
    double shutter_time = 0.0;
    // A lazy build's cells of this many objects or more are built one at a
    // time, the threads that reach another helping the one under way
    // (Hierarchy::build_pending): the memory a build holds while it runs
    // is then one large cell's, not one per thread. 0 or 1: every cell.
    std::size_t large_build = std::size_t(1) << 14;
    // A leaf of this many objects or more keeps no bins while it is
    // grouped: it is grouped by the objects' placed boxes at its ends and
    // makes their bins at the bottom (leaf_hierarchy.cpp; issue 43: a leaf
    // of 10^5 held 18.8 MB of packed bins, the swarm's peak). 0: every leaf.
    std::size_t kept_bins = std::size_t(1) << 14;
    // Statistics: count the cells a full build would make (counters.cells_full),
    // building what a lazy build left, after each hierarchy's use.
    bool count_full = false;

    // At most kMaxDepth, which bounds the traversal's stack.
    int depth_limit() const {
        const int d = max_depth > 0 ? max_depth : criterion == Criterion::Paper ? 5 : 24;
        return d < kMaxDepth ? d : kMaxDepth;
    }
    static constexpr int kMaxDepth = 32;
};

// The bounded objects and their sweeps (runtime/bounds/time_sweep.hpp), computed
// once over `time` and shared by every hierarchy built over part of it.
struct SweptObjects {
    std::vector<const runtime::IntelligentObject*> objects;
    std::vector<runtime::TimeSweep> sweeps;
    runtime::Interval time;

    // Sweeps for all objects in parallel, with at most 2^depth pieces each,
    // where depth = min(kMaxSweepDepth, log2(kSweepPieceBudget / moving
    // objects)): memory stays linear in the objects and does not grow with
    // the frame count.
    // With options.rays_per_frame known, each object's pieces are priced
    // against the rays expected to meet them (runtime::SweepPricing), the
    // rays spread over the surface of `scene` (the root's box).
    static SweptObjects of(std::span<const runtime::IntelligentObject* const> objects,
                           const runtime::Box4& scene, const BuildOptions& options);
    std::size_t bytes() const;
};

inline constexpr int kMaxSweepDepth = 8;
// 2^21 pieces, 48 MB: it binds past 8,192 moving objects. At 10^5 swarm
// spheres (16 pieces each instead of 32) the same cells, tests and images,
// 27 MB less; at 2^20 (8 pieces) the cost criterion, pricing upper cells
// from looser boxes, chose cells that tested 3.5 times the objects.
inline constexpr std::size_t kSweepPieceBudget = std::size_t(1) << 21;

// The objects a cell holds (indices into SweptObjects). Shared: a cell
// halved in time mostly hands all of its objects to both halves, and 64
// pending slabs of 10^5 objects each kept a copy (25 MB).
using ObjectList = std::shared_ptr<const std::vector<std::uint32_t>>;

// A cell whose node is not built yet.
struct PendingCell {
    runtime::Box4 region;
    int time_level = -1;  // its time as a dyadic piece of the sweeps' (Hierarchy::CellTime)
    std::uint64_t time_index = 0;
    ObjectList objects;
    int depth = 0;
    tbb::collaborative_once_flag once;  // threads that wait help build
    NodeRef built;
    // Where the cell's nodes go: the arena of the subtree it is in.
    NodeArena* arena = nullptr;
    // A slab root is the first cell no longer than a frame below the
    // hierarchy's lasting part: its subtree lives in an arena of its own
    // (`own`), which Hierarchy::release_outside frees when the frames no
    // longer need its time; it keeps its objects to be built again.
    bool slab_root = false;
    std::unique_ptr<NodeArena> own;
    // The slot that holds it, set when its build begins (Hierarchy::expand).
    NodeRef* slot = nullptr;
    // Its objects' count, kept: `objects` is let go once a cell is built.
    std::size_t object_count = 0;
};

class Hierarchy {
  public:
    // Builds the root cell's node over `root` (eager: the whole hierarchy).
    // The objects must outlive the hierarchy.
    Hierarchy(const SweptObjects& objects, const runtime::Box4& root, const BuildOptions& options,
              Counters& counters);
    ~Hierarchy();
    Hierarchy(const Hierarchy&) = delete;
    Hierarchy& operator=(const Hierarchy&) = delete;

    bool empty() const { return root_.empty(); }
    NodeRef root() const { return root_; }
    const runtime::Box4& region() const { return region_; }
    const SweptObjects& objects() const { return objects_; }
    const BuildOptions& options() const { return options_; }

    // The node a pending child stands for, built now if no thread has yet;
    // the slot that held it then holds the node. Thread-safe. Its time goes
    // to counters.lazy_build_seconds.
    NodeRef expand(NodeRef* slot, NodeRef pending, Counters& counters) const;

    // Builds every pending cell (one thread), counting them in
    // counters.cells_full beside those built already: what a full build
    // makes. For statistics only, after rendering; the slabs it builds are
    // released again as it goes, so that it needs no more memory than a
    // frame does.
    void count_full(Counters& counters) const;

    // Frees the subtrees of the slab roots (PendingCell::slab_root) whose
    // time lies outside [t0, t1], turning them back into pending cells: a
    // ray that reaches one later builds it again. Memory then stays what
    // the frames in use need, not what the whole animation does. Not
    // thread-safe: call it between frames, with no ray in flight.
    void release_outside(double t0, double t1);

    // release_outside(t0, t1), then the time index over [t0, t1]
    // (time_index.hpp): what a frame calls before its rays. Not
    // thread-safe, as release_outside.
    void enter_frame(double t0, double t1);
    // Where the walk of a ray at instant t starts: its piece of the time
    // index, or `root` (a copy of root()) where the index has none. Read
    // from the thread's own copy, `local`, taken again whenever the shared
    // index has changed since (enter_frame, a slab's release).
    NodeRef* time_entry(double t, NodeRef* root, LocalTimeIndex& local) const {
        // (Generations are unique across hierarchies: one number says both.)
        const std::uint64_t generation = index_generation_.load(std::memory_order_acquire);
        if (local.generation != generation) [[unlikely]] {
            local.index = time_index_;
            local.generation = generation;
        }
        return local.index.entry(t, root);
    }
    // The thread's copy built again from the chain as it stands, when a
    // walk from one of its entries met a time node built since. Thread-safe
    // (it reads the chain as a walk does, and writes `local` only).
    void refresh_time_index(LocalTimeIndex& local) const {
        // (The index never hands out the root's own slot: a chain starts
        // below it. The cast is for the type of the slots it keeps.)
        local.index.refresh(const_cast<NodeRef*>(&root_));
    }

    // Node memory in bytes: now, and the most held at once so far.
    std::size_t bytes() const;
    std::size_t peak_bytes() const;

  private:
    class Builder;
    struct CellTime;

    const SweptObjects& objects_;
    BuildOptions options_;
    runtime::Box4 region_;
    mutable NodeArena arena_;  // the lasting part: everything above the slab roots
    // The slab roots built now, and the slots that hold their nodes.
    struct LiveSlab {
        NodeRef* slot;
        PendingCell* cell;
    };
    mutable std::mutex slabs_mutex_;
    mutable std::vector<LiveSlab> live_slabs_;
    mutable std::size_t peak_bytes_ = 0;
    void release(const LiveSlab& slab) const;
    // Builds a pending cell (inside its once flag). Cells of
    // options_.large_build objects or more are built one at a time
    // (Hierarchy::expand reserves large_build_ first): threads build one
    // large cell together rather than one each, so that a build's
    // transient memory (about 130 bytes an object) is one cell's.
    void build_pending(PendingCell* p, Counters& counters) const;
    mutable std::atomic<PendingCell*> large_build_{nullptr};
    // The lasting part's bytes and every live slab's; slabs_mutex_ held.
    std::size_t held_bytes() const;
    mutable double root_area_ = 0.0;  // the root cell's time-averaged area (cost criterion)
    std::unique_ptr<Builder> builder_;
    NodeRef root_;
    // Cleared by every release of a slab (its slots go with it).
    mutable TimeIndex time_index_;
    // Changed with time_index_, to a number no hierarchy has used: the
    // threads' copies (LocalTimeIndex) are taken again.
    mutable std::atomic<std::uint64_t> index_generation_{0};
    void new_index_generation() const;
};

}  // namespace hexant::tracer
