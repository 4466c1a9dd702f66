// A box whose sides move linearly over a piece of time: what an object
// occupies over a short piece when its sweep follows the motion (the
// first-order Taylor form of runtime/time/interval_jet.hpp) instead of holding one box
// for the whole piece. At instant t of [t0, t1] the surface lies in
//   lo0 + u (lo1 - lo0) .. hi0 + u (hi1 - hi0),  u = (t - t0) / (t1 - t0),
// per axis. The same shape as the hierarchy's linear-motion nodes
// (tracer/cell.hpp), at the object level.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/vec3.hpp>

#include "runtime/geometry/spacetime.hpp"
#include "runtime/time/interval.hpp"

namespace hexant::runtime {

struct MovingBox {
    Interval time{0.0, 0.0};
    glm::dvec3 lo0{0.0}, lo1{0.0}, hi0{0.0}, hi1{0.0};
    bool empty = true;

    // A box that holds still over `time` (its space part).
    static MovingBox constant(const Box4& box, const Interval& time) {
        MovingBox m;
        m.time = time;
        if (box.is_empty()) return m;
        m.empty = false;
        for (int k = 0; k < 3; ++k) {
            m.lo0[k] = m.lo1[k] = box.lo[k];
            m.hi0[k] = m.hi1[k] = box.hi[k];
        }
        return m;
    }

    // The box over the part of `time` in `t`: each side's extreme over it
    // lies at an end of the part (the sides are lines). Rounding of the
    // interpolation (a few ulps of the ends' magnitudes, the quotient u
    // included) is paid outward.
    Box4 box_over(const Interval& t) const {
        const double a = std::max(t.lo, time.lo), b = std::min(t.hi, time.hi);
        if (empty || !(a <= b)) return Box4::empty();
        const double span = time.hi - time.lo;
        const auto u = [&](double x) {
            return span > 0.0 ? std::clamp((x - time.lo) / span, 0.0, 1.0) : 0.0;
        };
        const double ua = u(a), ub = u(b);
        Box4 r;
        for (int k = 0; k < 3; ++k) {
            const double lo_a = lo0[k] + ua * (lo1[k] - lo0[k]),
                         lo_b = lo0[k] + ub * (lo1[k] - lo0[k]);
            const double hi_a = hi0[k] + ua * (hi1[k] - hi0[k]),
                         hi_b = hi0[k] + ub * (hi1[k] - hi0[k]);
            const double lo_margin = kSlack * std::max(std::fabs(lo0[k]), std::fabs(lo1[k]));
            const double hi_margin = kSlack * std::max(std::fabs(hi0[k]), std::fabs(hi1[k]));
            r.lo[k] = std::max(std::min(lo_a, lo_b) - lo_margin, std::min(lo0[k], lo1[k]));
            r.hi[k] = std::min(std::max(hi_a, hi_b) + hi_margin, std::max(hi0[k], hi1[k]));
        }
        r.lo.w = a;
        r.hi.w = b;
        return r;
    }

    // The box over the whole piece.
    Box4 hull() const { return box_over(time); }

    // Per side, the tighter of this box's line and o's (same time, both
    // holding the same thing): the one nearer the inside at mid-time.
    void tighten(const MovingBox& o) {
        if (o.empty) return;
        if (empty) {
            *this = o;
            return;
        }
        for (int k = 0; k < 3; ++k) {
            if (o.lo0[k] + o.lo1[k] > lo0[k] + lo1[k]) lo0[k] = o.lo0[k], lo1[k] = o.lo1[k];
            if (o.hi0[k] + o.hi1[k] < hi0[k] + hi1[k]) hi0[k] = o.hi0[k], hi1[k] = o.hi1[k];
        }
    }

    // 8 ulps: the interpolation's three roundings and u's two, each within
    // an ulp of the larger end, with room to spare.
    static constexpr double kSlack = 8.0 * std::numeric_limits<double>::epsilon();
};

}  // namespace hexant::runtime
