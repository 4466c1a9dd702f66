// Where to start a secondary ray so that it does not hit the surface it
// leaves: Wachter and Binder, "A Fast and Robust Method for Avoiding
// Self-Intersection" (Ray Tracing Gems, ch. 6), adapted to double.
//
// The hit point carries a rounding error of some ulps of its own coordinates
// (SurfaceHit::point is computed near the surface to keep it so). Stepping
// each coordinate a fixed number of ulps along the normal clears that error
// at every scale without knowing the scene's size: far from the origin the
// step is made on the coordinate's bit pattern as an integer. A coordinate
// near zero has ulps that shrink without bound while its error (inherited
// from the other, larger coordinates of the computation) does not, so it
// steps by a part of the point's largest coordinate instead. The paper
// takes that scale as 1 (its crossover 1/32 and step 2^-16 are absolute);
// here the largest coordinate is the unit, so that a scene drawn a
// thousand times smaller (or larger) starts its rays at the same relative
// places, and a power-of-two scale gives the same image.
//
// Constants for double (the paper's are for float, 24-bit significand):
// - kOffsetIntScale = 256: the step in ulps per unit of normal component;
//   the paper's value, since the error counted in ulps of the point is about
//   the same in any precision (a few dozen ulps at most for our routines).
// - kOffsetOrigin = 1/32: the paper's crossover, a part of the point's
//   largest coordinate |p|max.
// - kOffsetFloatScale = 2^-45: the paper's 2^-16 scaled by 2^-29, the ratio
//   of the two precisions' ulps (2^-52 / 2^-23), times |p|max, so that near
//   the crossover the step stays 16 times the integer step as in the paper
//   (256 ulps of |p|max / 32 in double is about 2^-49 |p|max).
// The normal must face the side the new ray leaves toward: the geometric
// normal for reflection, its negation for transmission.
//
// That step covers the error of the point relative to its own coordinates.
// A hit's error also grows with the shape's coordinates (a sphere of radius
// 1e5 touching y = 0 has its top's y off by about 1e-11, where ulps of y are
// far smaller): the three-argument offset_ray first moves the point past
// the hit's own error bound along the normal (pbrt-v4's OffsetRayOrigin:
// the bound's projection on |n|, each coordinate rounded away from the
// point), then takes the step above.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include <glm/glm.hpp>

#include "runtime/geometry/ray3.hpp"

namespace hexant::runtime::geometry {

inline constexpr double kOffsetOrigin = 1.0 / 32.0;
inline constexpr double kOffsetFloatScale = 0x1p-45;
inline constexpr double kOffsetIntScale = 256.0;

inline glm::dvec3 offset_ray(const glm::dvec3& p, const glm::dvec3& n) {
    // The point's own scale; a point at the top of the range (or not
    // finite) takes integer steps only, which never leave the range.
    const double scale = std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
    const bool scaled = std::isfinite(scale);
    const double near_zero = scaled ? kOffsetOrigin * scale : 0.0;
    const double step_near_zero = kOffsetFloatScale * scale;
    glm::dvec3 out;
    for (int k = 0; k < 3; ++k) {
        if (!(std::fabs(n[k]) <= 2.0)) {  // not a unit normal (or NaN): leave it
            out[k] = p[k];
            continue;
        }
        if (std::fabs(p[k]) < near_zero) {
            out[k] = p[k] + step_near_zero * n[k];
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

// The error bound of a hit's world point `world`, the image of the shape's
// point p (known to within `error`) under a map whose linear part at p is
// `linear` (glm's column-major 3x3: the placement's, or a deformation's
// Jacobian), after pbrt-v4's transform of a Point3fi: the input's error
// goes through |linear|, and the map rounds within some ulps of the
// magnitudes it adds (|linear| |p| and the rest, world - linear p: the
// translation). gamma(32) covers a placement's products and sums, a
// deformation's sines and cosines (a few ulps each, deformation.hpp) and
// the way back into the shape's space of a secondary ray, for a
// well-conditioned map. Formed once per shaded hit (Primitive::complete).
inline glm::dvec3 world_error(const glm::dmat3& linear, const glm::dvec3& p,
                              const glm::dvec3& world, const glm::dvec3& error) {
    const glm::dvec3 image = linear * p;
    glm::dvec3 out;
    for (int i = 0; i < 3; ++i) {
        double carried = 0.0, magnitude = std::fabs(world[i]) + std::fabs(world[i] - image[i]);
        for (int j = 0; j < 3; ++j) {
            carried += std::fabs(linear[j][i]) * error[j];
            magnitude += std::fabs(linear[j][i] * p[j]);
        }
        out[i] = carried + rounding_gamma(32) * magnitude;
    }
    return is_finite(out) ? out : glm::dvec3(0.0);
}

// The start of a secondary ray leaving a hit at p, known to within `error`
// (SurfacePoint::error), toward the side n faces. An error that is not
// finite (a hit near the top of the double range) is left to the ulp step.
inline glm::dvec3 offset_ray(const glm::dvec3& p, const glm::dvec3& error, const glm::dvec3& n) {
    const double d = glm::dot(glm::abs(n), error);
    if (!(d > 0.0) || !std::isfinite(d)) return offset_ray(p, n);
    glm::dvec3 moved = p + d * n;
    // Round each moved coordinate away from p: the sum may have rounded
    // back toward the surface.
    for (int k = 0; k < 3; ++k) {
        if (n[k] > 0.0)
            moved[k] = std::nextafter(moved[k], std::numeric_limits<double>::infinity());
        else if (n[k] < 0.0)
            moved[k] = std::nextafter(moved[k], -std::numeric_limits<double>::infinity());
        if (!std::isfinite(moved[k])) moved[k] = p[k];
    }
    return offset_ray(moved, n);
}

}  // namespace hexant::runtime::geometry
