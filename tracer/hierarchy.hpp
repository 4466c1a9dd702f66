// Glassner's hybrid hierarchy: space (and time) subdivision down, bounding
// volumes up.
//
// Down: a cell (a 4D box) splits into 16 equal children, halving x, y, z and
// t, while the paper's criterion holds: more than `max_objects` objects meet
// the cell; or, with that many or fewer (but more than one), they fill less
// than `max_occupancy` of its volume; and never below `max_depth`. Time is
// halved only where something in the cell moves (8 spatial children
// otherwise), and a cell with one moving object halves its time only (2
// children): splitting space around a lone object cannot tighten its bound,
// splitting the time it sweeps can.
// Up: a leaf's bound is the union of its objects' 12-slab bounds inside the
// cell (each object clips to the region it is asked about); an inner cell's
// is the union of its children's. A cell with one child is replaced by it.
//
// The frame-by-frame baseline uses the same builder with SplitMode::Space:
// the root's time range is one frame's shutter interval, cells split 8 ways
// in x, y, z only, and every object bound is widened to the box it spans
// over the whole interval (static 3D slabs, as the paper's baseline).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "runtime/intelligent_object.hpp"
#include "runtime/slab_bound.hpp"
#include "runtime/spacetime.hpp"
#include "tracer/counters.hpp"

namespace hexant::tracer {

enum class SplitMode { Spacetime, Space };

struct BuildOptions {
    SplitMode split = SplitMode::Spacetime;
    int max_depth = 5;
    std::size_t max_objects = 3;
    double max_occupancy = 0.3;
    // SplitMode::Space only: widen each object's bound to its box, as the
    // paper's baseline. With false the builder keeps the 12-slab bounds and,
    // on a static scene, builds exactly the spacetime mode's hierarchy (the
    // "same hierarchy in 3D" that shows what the fourth dimension costs).
    bool boxes_in_space = true;
};

struct Cell {
    runtime::Box4 region;       // the part of spacetime this cell owns
    runtime::SlabBound bound;   // what its objects occupy inside region
    std::uint32_t first_child = 0, child_count = 0;    // children are consecutive
    std::uint32_t first_object = 0, object_count = 0;  // a leaf's object indices
    // The children halve time only (same space as this cell): a ray at one
    // instant meets exactly one of them, whose bound is tighter than this
    // cell's, so the walk goes straight to it.
    bool splits_time_only = false;
    bool is_leaf() const { return child_count == 0; }
};

class Hierarchy {
public:
    // objects[i] must be bounded. An empty hierarchy has no cells.
    static Hierarchy build(std::span<const runtime::IntelligentObject* const> objects,
                           const runtime::Box4& root, const BuildOptions& options,
                           Counters& counters);

    bool empty() const { return cells_.empty(); }
    const Cell& root() const { return cells_.front(); }
    const std::vector<Cell>& cells() const { return cells_; }
    // Object indices of a leaf.
    std::span<const std::uint32_t> objects_of(const Cell& leaf) const {
        return {object_refs_.data() + leaf.first_object, leaf.object_count};
    }
    int depth() const { return depth_; }

private:
    std::vector<Cell> cells_;
    std::vector<std::uint32_t> object_refs_;
    int depth_ = 0;
};

}  // namespace hexant::tracer
