// The chord bound (IntelligentObject::chord_bound_over) of a shape that does
// not change, carried by an affine motion: a primitive of a fixed shape, an
// instance's members (instance_object.hpp).
#pragma once

#include <cmath>
#include <limits>
#include <optional>

#include "runtime/motion/motion.hpp"
#include "runtime/objects/intelligent_object.hpp"
#include "runtime/objects/model_support.hpp"

namespace hexant::runtime {

// Over t, the motion's second derivative (interval jets, interval_jet.hpp)
// applied to the object box p, x'' = M''(t) (p, 1); the margin is twice the
// matrix entries' rounding radii times |p| (the exact ends against the
// double placed boxes, and the double placement at t against the exact
// one) plus the rounding of the product M (p, 1) itself. Nothing when the
// motion is not smooth over t (a jump or a kink) or the bound overflows.
// `motion` must be affine.
inline std::optional<IntelligentObject::ChordBound> rigid_chord_bound(const Motion& motion,
                                                                      const IntervalBox& p,
                                                                      const Interval& t) {
    const AffineMap<IntervalJet> m = motion.matrix_jet_over(t);
    constexpr double kProductRounding = 4.0 * std::numeric_limits<double>::epsilon();
    IntelligentObject::ChordBound bound;
    for (int i = 0; i < 3; ++i) {
        if (!m.m[i][3].smooth()) return std::nullopt;
        Interval second = m.m[i][3].dd;
        double radius = m.m[i][3].r, magnitude = m.m[i][3].v.magnitude();
        for (int j = 0; j < 3; ++j) {
            if (!m.m[i][j].smooth()) return std::nullopt;
            second = second + m.m[i][j].dd * p[j];
            radius += m.m[i][j].r * p[j].magnitude();
            magnitude += m.m[i][j].v.magnitude() * p[j].magnitude();
        }
        bound.acceleration[i] = second.magnitude();
        bound.margin[i] = interval_detail::up(2.0 * radius + kProductRounding * magnitude, 4);
        if (!std::isfinite(bound.acceleration[i]) || !std::isfinite(bound.margin[i]))
            return std::nullopt;
    }
    return bound;
}

}  // namespace hexant::runtime
