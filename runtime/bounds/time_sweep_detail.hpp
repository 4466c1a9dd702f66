// What time_sweep.cpp (a sweep's storage and questions) and
// time_sweep_of.cpp (making a sweep) share: rounding to floats outward,
// and a box's largest extent.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "runtime/geometry/spacetime.hpp"

namespace hexant::runtime::time_sweep_detail {

// The float at or above x (+infinity past the floats' range or for NaN,
// which makes a chord's box infinite: the cached piece is kept).
inline float float_up(double x) {
    if (!(x <= double(std::numeric_limits<float>::max())))
        return std::numeric_limits<float>::infinity();
    // Below the floats' range (a conversion there is undefined): the lowest float is above x.
    if (x < -double(std::numeric_limits<float>::max())) return -std::numeric_limits<float>::max();
    float f = float(x);
    if (double(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
    return f;
}

// The float at or below x (-infinity past the floats' range or for NaN).
inline float float_down(double x) {
    return -float_up(-x);
}

inline double largest_extent(const Box4& b) {
    if (b.is_empty()) return 0.0;
    return std::max({b.hi.x - b.lo.x, b.hi.y - b.lo.y, b.hi.z - b.lo.z});
}

}  // namespace hexant::runtime::time_sweep_detail
