// The linear-motion box (cell.hpp's MotionNode): a box whose ends move
// linearly over a node's time, fitted under and over boxes that hold the
// contents over equal pieces ("bins") of that time. For each coordinate and
// side the line is the one that stays outside every bin and lies closest
// to the contents on average (it maximises the lower end's mean, i.e. its
// value at mid-time): the supporting line of the bins' lower convex hull at
// mid-time, as Embree's linear bounds follow motion but conservative by
// construction. Doubles throughout; bound_rounding.hpp stores the result.
#pragma once

#include <algorithm>
#include <array>
#include <limits>

#include <glm/vec3.hpp>

#include "runtime/geometry/spacetime.hpp"

namespace hexant::tracer {

// The most bins a TimeBins holds: the builder's (hierarchy_builder.hpp's
// kFitBins). Every child under construction carries its bins, so their
// size is the build's memory traffic: 224 bytes at four, 416 at eight.
inline constexpr int kMaxBins = 4;

// One bin's box: the space part of a Box4 in single precision, rounded
// outward (float_down, float_up), so it holds whatever the doubles held.
// 24 bytes where a Box4 takes 64: a leaf of 10^5 objects, each with eight
// bins, keeps them in 20 MB instead of 52 while it is built. The nodes
// store floats anyway; a bin's time is its piece of the node's time.
struct BinBox {
    std::array<float, 3> lo{kFloatInf, kFloatInf, kFloatInf};
    std::array<float, 3> hi{-kFloatInf, -kFloatInf, -kFloatInf};

    static BinBox of(const runtime::Box4& box);  // empty if the box is
    static BinBox of(const glm::dvec3& lo, const glm::dvec3& hi);
    bool is_empty() const { return !(lo[0] <= hi[0] && lo[1] <= hi[1] && lo[2] <= hi[2]); }
    void extend(const BinBox& o) {
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], o.lo[k]);
            hi[k] = std::max(hi[k], o.hi[k]);
        }
    }
    // The part inside the region's space (rounded outward: it may keep a
    // sliver of the region's float rounding, never lose a point).
    BinBox clipped(const runtime::Box4& region) const;
    // Back in doubles, over time t.
    runtime::Box4 box(const runtime::Interval& t) const;
    bool operator==(const BinBox&) const = default;

  private:
    static constexpr float kFloatInf = std::numeric_limits<float>::infinity();
};

// Boxes over `count` equal pieces of a time range (an empty bin holds
// nothing then), and where `lined`, the contents' bound at each of the
// count + 1 cuts between the pieces ("edges"), such that over bin b the
// contents also lie between the lines from edge b to edge b + 1: the sides
// of a moving box (runtime::TimeSweep::boxes_over_dyadic). A bin's box
// holds everything its piece of time sweeps; the lines hold what is there
// at each instant, about the object's own size where it moves along a
// chord (issue 43: a swarm sphere's boxes over a leaf's bins were three
// times its size along its path).
struct TimeBins {
    int count = 0;
    std::array<BinBox, kMaxBins> bin;
    bool lined = false;
    std::array<BinBox, kMaxBins + 1> edge;

    // Nothing yet; lined, so that add() keeps the lines of what it adds.
    static TimeBins empty(int count) {
        TimeBins b;
        b.count = count;
        b.lined = true;
        return b;
    }
    bool is_empty() const {
        for (int i = 0; i < count; ++i)
            if (!bin[i].is_empty()) return false;
        return true;
    }
    // Lines that can be used: lined, and both edges of every non-empty bin there.
    bool lines() const;
    // Everything of both (lines only where both have them).
    void add(const TimeBins& o) {
        for (int i = 0; i < count; ++i) bin[i].extend(o.bin[i]);
        lined = lined && o.lined;
        if (lined)
            for (int i = 0; i <= count; ++i) edge[i].extend(o.edge[i]);
    }
    // The part inside the region's space. A bin's box is clipped; an edge
    // is raised to the region's side only where the lines on both sides of
    // it lie wholly outside that side (a line crossing it keeps its ends:
    // clipping one end would cut off what the line holds inside).
    TimeBins clipped(const runtime::Box4& region) const;
    // The box over all bins (their space part), and over the edges too
    // where lined (what PackedBins steps over).
    BinBox hull() const {
        BinBox h;
        for (int i = 0; i < count; ++i) h.extend(bin[i]);
        return h;
    }
    BinBox frame() const {
        BinBox h = hull();
        if (lined)
            for (int i = 0; i <= count; ++i) h.extend(edge[i]);
        return h;
    }
    // The same over time t (the bins' whole time).
    runtime::Box4 hull(const runtime::Interval& t) const { return hull().box(t); }
    // The mean over the bins of the surface areas (0 for empty bins) of
    // their boxes, or where lined, of what holds the contents at each
    // bin's mid-time (the box there, inside the lines): an estimate of the
    // area a ray at a random instant sees.
    double mean_area() const;
};

// A bound moving linearly from `start` to `end` over a time range: how the
// union of moving objects' bounds is held where each moves about linearly
// (Embree's LBBox). The leaf builder prices its groups by it.
struct LinearExtent {
    BinBox start, end;

    void extend(const LinearExtent& o) {
        start.extend(o.start);
        end.extend(o.end);
    }
    // The time-averaged surface area of the interpolated box.
    double mean_area() const;
};

// Ends at the start (u = 0) and at the end (u = 1) of the time range.
struct LinearBox {
    glm::dvec3 lo0{0.0}, lo1{0.0}, hi0{0.0}, hi1{0.0};
    bool empty = true;

    // The time-averaged surface area (exact for the interpolated box).
    double mean_area() const;
};

// The linear-motion box over all bins: below (above) each non-empty bin's
// box over its piece of time, or where the bins are lined, below its line
// when that is the nearer on average.
LinearBox fit_linear(const TimeBins& bins);
// The same over one bin, its lines from `first` to `last` where `lined`
// (both then non-empty): what fit_linear gives a TimeBins of that one
// bin, without building it (a piece node fits each of its children's
// pieces so, four a child).
LinearBox fit_linear(const BinBox& bin, const BinBox& first, const BinBox& last, bool lined);

// Surface area of a box's space part (0 for an empty box).
double surface_area(const runtime::Box4& box);
double surface_area(const BinBox& box);  // of its space part; 0 if empty

}  // namespace hexant::tracer
