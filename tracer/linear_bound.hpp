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

inline constexpr int kMaxBins = 8;

// One bin's box: the space part of a Box4 in single precision, rounded
// outward (float_down, float_up), so it holds whatever the doubles held.
// 24 bytes where a Box4 takes 64: a leaf of 10^5 objects, each with eight
// bins, keeps them in 20 MB instead of 52 while it is built. The nodes
// store floats anyway; a bin's time is its piece of the node's time.
struct BinBox {
    std::array<float, 3> lo{kFloatInf, kFloatInf, kFloatInf};
    std::array<float, 3> hi{-kFloatInf, -kFloatInf, -kFloatInf};

    static BinBox of(const runtime::Box4& box);  // empty if the box is
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
// nothing then).
struct TimeBins {
    int count = 0;
    std::array<BinBox, kMaxBins> bin;

    static TimeBins empty(int count) {
        TimeBins b;
        b.count = count;
        return b;
    }
    bool is_empty() const {
        for (int i = 0; i < count; ++i)
            if (!bin[i].is_empty()) return false;
        return true;
    }
    void add(const TimeBins& o) {
        for (int i = 0; i < count; ++i) bin[i].extend(o.bin[i]);
    }
    // The box over all bins (their space part).
    BinBox hull() const {
        BinBox h;
        for (int i = 0; i < count; ++i) h.extend(bin[i]);
        return h;
    }
    // The same over time t (the bins' whole time).
    runtime::Box4 hull(const runtime::Interval& t) const { return hull().box(t); }
    // The mean over the bins of their boxes' surface areas (0 for empty
    // bins): an estimate of the area a ray at a random instant sees.
    double mean_area() const;
};

// Ends at the start (u = 0) and at the end (u = 1) of the time range.
struct LinearBox {
    glm::dvec3 lo0{0.0}, lo1{0.0}, hi0{0.0}, hi1{0.0};
    bool empty = true;

    // The time-averaged surface area (exact for the interpolated box).
    double mean_area() const;
};

LinearBox fit_linear(const TimeBins& bins);

// Surface area of a box's space part (0 for an empty box).
double surface_area(const runtime::Box4& box);
double surface_area(const BinBox& box);  // of its space part; 0 if empty

}  // namespace hexant::tracer
