// The paper's bounding volume: for each of twelve fixed 4D directions, the
// range of n · e over the bounded events (Kay and Kajiya's slabs, in
// spacetime). Four normals are the principal axes x, y, z, t; eight are
// (.5, ±.5, ±.5, ±.5), which cut the corners a box leaves around anything
// moving diagonally in space and time.
//
// Every range is rounded outward, so a bound holds the exact dot products of
// all that was added, not only their double approximations.
#pragma once

#include <array>

#include "runtime/geometry/spacetime.hpp"

namespace hexant::runtime {

inline constexpr int kSlabCount = 12;

// The twelve unit normals: x, y, z, t, then (.5, ±.5, ±.5, ±.5) with the
// signs of y, z, t from the bits of (index - 4), bit 0 for t.
const std::array<Event, kSlabCount>& slab_normals();

struct SlabBound {
    std::array<double, kSlabCount> lo;
    std::array<double, kSlabCount> hi;

    static SlabBound empty();
    static SlabBound of_box(const Box4& box);

    bool is_empty() const;
    void add(const Box4& box);
    void add(const Event& event);
    void add(const SlabBound& other);
    // Narrows the bound to the part inside the box (each slab to the box's
    // own range of that dot product).
    void clip(const Box4& box);
    // Whether the event may lie inside: its dot products, enclosed by
    // intervals, meet every slab.
    bool contains(const Event& event) const;
    // The principal slabs as a box.
    Box4 box() const;
};

}  // namespace hexant::runtime
