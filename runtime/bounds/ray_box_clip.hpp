// Narrowing a ray's parameter range to a box before the costlier curved-path
// search: the box is a conservative bound (in world space) of the object.
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>

#include <glm/vec3.hpp>

#include "runtime/objects/model_support.hpp"

namespace hexant::runtime {

// Narrows [s_lo, s_hi] to where origin + s direction lies in the box, and
// says whether anything is left. The box and the resulting range are widened
// by a few parts in 1e15 of the numbers involved (relative, so at any scale),
// so that rounding here never cuts off a point the box holds.
inline bool clip_ray_to_box(const glm::dvec3& origin, const glm::dvec3& direction,
                            const IntervalBox& box, double& s_lo, double& s_hi) {
    constexpr double kWiden = 8.0 * 1.1102230246251565e-16;
    for (int i = 0; i < 3; ++i) {
        if (!(box[i].lo <= box[i].hi)) return false;
        const double scale =
            std::max({std::fabs(box[i].lo), std::fabs(box[i].hi), std::fabs(origin[i])});
        const double lo = box[i].lo - kWiden * scale, hi = box[i].hi + kWiden * scale;
        if (direction[i] == 0.0) {
            if (origin[i] < lo || origin[i] > hi) return false;
            continue;
        }
        double enter = (lo - origin[i]) / direction[i], leave = (hi - origin[i]) / direction[i];
        if (enter > leave) std::swap(enter, leave);
        s_lo = std::max(s_lo, enter - kWiden * std::fabs(enter));
        s_hi = std::min(s_hi, leave + kWiden * std::fabs(leave));
        if (!(s_lo <= s_hi)) return false;
    }
    return true;
}

}  // namespace hexant::runtime
