// The linear-motion box (cell.hpp's MotionNode): a box whose ends move
// linearly over a node's time, fitted under and over boxes that hold the
// contents over equal pieces ("bins") of that time. For each coordinate and
// side the line is the one that stays outside every bin and lies closest
// to the contents on average (it maximises the lower end's mean, i.e. its
// value at mid-time): the supporting line of the bins' lower convex hull at
// mid-time, as Embree's linear bounds follow motion but conservative by
// construction. Doubles throughout; bound_rounding.hpp stores the result.
#pragma once

#include <array>
#include <glm/vec3.hpp>

#include "runtime/spacetime.hpp"

namespace hexant::tracer {

inline constexpr int kMaxBins = 8;

// Boxes over `count` equal pieces of a time range (space parts of Box4s;
// an empty bin holds nothing then).
struct TimeBins {
    int count = 0;
    std::array<runtime::Box4, kMaxBins> bin;

    static TimeBins empty(int count) {
        TimeBins b;
        b.count = count;
        for (int i = 0; i < count; ++i) b.bin[i] = runtime::Box4::empty();
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
    // The box over all bins (space part).
    runtime::Box4 hull() const {
        runtime::Box4 h = runtime::Box4::empty();
        for (int i = 0; i < count; ++i) h.extend(bin[i]);
        return h;
    }
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

}  // namespace hexant::tracer
