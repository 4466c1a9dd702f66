// The time index (docs/design.md, "Traversal"): the slots below the
// hierarchy's chain of time nodes over one frame's shutter, in time order,
// so that a ray at one instant starts its walk at the subtree of its own
// time slice instead of descending the chain node by node (Embree's
// time-segment arrays play the same part for its motion blur).
//
// The chain is the cost criterion's answer for an animation: the root cell
// halved in time seven times over the atom's 64 frames, every ray taking
// seven dependent loads before its first bound. The index holds the slots
// the chain ends at inside the frame's shutter (at most kMaxEntries): one
// search in a short array of doubles, then the subtree. A walk started at
// an indexed slot meets exactly what the chain would have led it to, since
// each entry is the child the chain picks for every instant of its piece
// (an instant on a cut goes to the later piece, as at a time node).
//
// Built between frames (Hierarchy::enter_frame), after the slabs outside
// the frame are let go; cleared whenever a slab is released, since its
// slots die with it (a slot indexed while pending stays valid: the walk's
// build stores its node there). Not thread-safe to build; read by any
// thread.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "tracer/cell.hpp"

namespace hexant::tracer {

class TimeIndex {
  public:
    // More pieces than a frame has samples in time would not pay.
    static constexpr std::size_t kMaxEntries = 4096;

    // Reads the chain of time nodes below *root over [t0, t1], as far as it
    // is built: a pending cell ends its piece, and the walk builds it when
    // a ray first reaches it, as before (building the chain here, on one
    // thread, took the swarm's slices from the render's threads and
    // doubled its time). Empty (every walk starts at the root) where the
    // root is not a time node.
    void build(NodeRef* root, double t0, double t1);
    void clear();
    // Builds it again over the same shutter, reaching below the time nodes
    // built since (a thread's own copy, LocalTimeIndex; the chain is read
    // as a walk reads it, so other threads may build meanwhile).
    void refresh(NodeRef* root) { build(root, t0_, t1_); }
    // Whether a walk from an entry that meets a time node would gain by a
    // refresh: built over a shutter, and not stopped by kMaxEntries (past
    // that, walks take the time nodes below it as before).
    bool refreshable() const { return !slots_.empty() && !capped_; }

    // The slot a walk at instant t starts from: the indexed piece holding
    // t, or `root` where t lies outside the index.
    NodeRef* entry(double t, NodeRef* root) const {
        const std::size_t n = slots_.size();
        if (n == 0 || !(t >= cuts_[0] && (t < cuts_[n] || (t == cuts_[n] && end_closed_))))
            return root;
        // The first inner cut above t: t in [cuts[k], cuts[k + 1]).
        std::size_t lo = 0, hi = n - 1;  // the answer k lies in [lo, hi]
        while (lo < hi) {
            const std::size_t mid = (lo + hi + 1) / 2;
            if (t >= cuts_[mid])
                lo = mid;
            else
                hi = mid - 1;
        }
        return slots_[lo];
    }
    std::size_t size() const { return slots_.size(); }

  private:
    std::vector<double> cuts_;     // size() + 1 times, increasing
    std::vector<NodeRef*> slots_;  // piece k holds [cuts_[k], cuts_[k + 1])
    // The last piece holds its end too only where that is the chain's end
    // (elsewhere an instant there belongs to a later piece not indexed).
    bool end_closed_ = false;
    bool capped_ = false;  // a piece was kept whole because the index was full
    double t0_ = 0.0, t1_ = -1.0;
};

// A thread's copy of a hierarchy's time index (ThreadState): taken from the
// shared one when that changes (`generation`, Hierarchy::time_entry), and
// refreshed by the thread alone when a walk from one of its entries meets
// a time node, so that within a frame each ray starts below the chain the
// frame's first rays built (issue 43: bounce's rays walked about three time
// nodes below the shared index, built before the frame's own cells).
struct LocalTimeIndex {
    TimeIndex index;
    // The generation of the Hierarchy's index it copies (unique to that
    // hierarchy and that index; 0: none yet).
    std::uint64_t generation = 0;
};

}  // namespace hexant::tracer
