// What every shape model (runtime/objects/*_model.hpp) shares: boxes made of
// intervals, and how far a time-varying parameter strays from its value at
// one instant. A model turns a shape record's time functions into the static
// geometry of runtime/geometry at an instant, and bounds it over an interval
// of time.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/vec3.hpp>

#include "runtime/geometry/ray3.hpp"
#include "runtime/time/compiled_function.hpp"
#include "runtime/time/interval.hpp"

namespace hexant::runtime::objects {

inline IntervalBox empty_interval_box() {
    const double inf = std::numeric_limits<double>::infinity();
    return {Interval(inf, -inf), Interval(inf, -inf), Interval(inf, -inf)};
}

inline IntervalBox hull(const IntervalBox& a, const IntervalBox& b) {
    return {hull(a[0], b[0]), hull(a[1], b[1]), hull(a[2], b[2])};
}

inline IntervalBox to_interval_box(const geometry::Box3& box) {
    return {Interval(box.lo.x, box.hi.x), Interval(box.lo.y, box.hi.y),
            Interval(box.lo.z, box.hi.z)};
}

// The box around every ball of radius in `radius` centred anywhere in `center`.
inline IntervalBox ball_box(const IntervalBox& center, const Interval& radius) {
    const double r = std::max(radius.hi, 0.0);
    IntervalBox out;
    for (int i = 0; i < 3; ++i) out[i] = center[i] + Interval(-r, r);
    return out;
}

// An upper bound of |v(t) - at_mid| over t: how far a vector parameter moves
// from its value at one instant during an interval of time. Models add these
// up into a bound of how far their surface moves (a Hausdorff distance).
inline double deviation(const CompiledVector3& v, const Interval& t, const glm::dvec3& at_mid) {
    if (v.is_constant()) return 0.0;
    const IntervalBox range = v.over(t);
    double sum = 0.0;
    for (int i = 0; i < 3; ++i) {
        const double d = (range[i] - Interval(at_mid[i])).magnitude();
        sum += d * d;
    }
    // sqrt is correctly rounded; one ulp up covers the rounding of the sum.
    return std::nextafter(std::sqrt(sum) * (1.0 + 4.0 * 1.1102230246251565e-16),
                          std::numeric_limits<double>::infinity());
}

inline double deviation(const CompiledScalar& f, const Interval& t, double at_mid) {
    if (f.is_constant()) return 0.0;
    return (f.over(t) - Interval(at_mid)).magnitude();
}

}  // namespace hexant::runtime::objects
