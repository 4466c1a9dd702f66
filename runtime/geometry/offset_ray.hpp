// Where to start a secondary ray so that it does not hit the surface it
// leaves: Wachter and Binder, "A Fast and Robust Method for Avoiding
// Self-Intersection" (Ray Tracing Gems, ch. 6), adapted to double.
//
// The hit point carries a rounding error of some ulps of its own coordinates
// (SurfaceHit::point is computed near the surface to keep it so). Stepping
// each coordinate a fixed number of ulps along the normal clears that error
// at every scale without knowing the scene's size: far from the origin the
// step is made on the coordinate's bit pattern as an integer. Near zero a
// coordinate's ulps shrink without bound while the error (inherited from the
// other, larger coordinates of the computation) does not, so below
// kOffsetOrigin a fixed absolute step is used instead.
//
// Constants for double (the paper's are for float, 24-bit significand):
// - kOffsetIntScale = 256: the step in ulps per unit of normal component;
//   the paper's value, since the error counted in ulps of the point is about
//   the same in any precision (a few dozen ulps at most for our routines).
// - kOffsetOrigin = 1/32: the paper's crossover magnitude, kept.
// - kOffsetFloatScale = 2^-45: the paper's 2^-16 scaled by 2^-29, the ratio
//   of the two precisions' ulps (2^-52 / 2^-23), so that near the crossover
//   the absolute step stays 16 times the integer step as in the paper
//   (256 ulps of 1/32 in double is 2^-49).
// The normal must face the side the new ray leaves toward: the geometric
// normal for reflection, its negation for transmission.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>

namespace hexant::runtime::geometry {

inline constexpr double kOffsetOrigin = 1.0 / 32.0;
inline constexpr double kOffsetFloatScale = 0x1p-45;
inline constexpr double kOffsetIntScale = 256.0;

inline glm::dvec3 offset_ray(const glm::dvec3& p, const glm::dvec3& n) {
    glm::dvec3 out;
    for (int k = 0; k < 3; ++k) {
        if (std::fabs(p[k]) < kOffsetOrigin) {
            out[k] = p[k] + kOffsetFloatScale * n[k];
            continue;
        }
        if (!(std::fabs(n[k]) <= 2.0)) {  // not a unit normal (or NaN): leave it
            out[k] = p[k];
            continue;
        }
        // Moving the bit pattern of a positive double up by one steps it one
        // ulp away from zero (for negative ones, toward more negative), so
        // the step's sign follows both n's and p's signs.
        const auto step = static_cast<std::int64_t>(kOffsetIntScale * n[k]);
        const auto bits = std::bit_cast<std::int64_t>(p[k]);
        const double moved = std::bit_cast<double>(p[k] < 0.0 ? bits - step : bits + step);
        // Never step into Inf or NaN at the top of the range.
        out[k] = std::isfinite(moved) ? moved : p[k];
    }
    return out;
}

}  // namespace hexant::runtime::geometry
