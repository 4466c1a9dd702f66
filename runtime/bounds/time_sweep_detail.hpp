// What time_sweep.cpp (a sweep's storage and questions) and
// time_sweep_of.cpp (making a sweep) share: rounding to floats outward,
// and a box's largest extent.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "runtime/geometry/float_rounding.hpp"
#include "runtime/geometry/spacetime.hpp"

namespace hexant::runtime::time_sweep_detail {

// Rounding outward to floats (geometry/float_rounding.hpp).
using geometry::float_down;
using geometry::float_up;

inline double largest_extent(const Box4& b) {
    if (b.is_empty()) return 0.0;
    return std::max({b.hi.x - b.lo.x, b.hi.y - b.lo.y, b.hi.z - b.lo.z});
}

}  // namespace hexant::runtime::time_sweep_detail
