// A 4D ray prepared for testing against 12-slab bounds: its dot products
// with the twelve normals are computed once per ray (Kay and Kajiya), so a
// test is two subtractions and two multiplications per slab.
//
// Robust in the sense of Ize ("Robust BVH Ray Traversal", JCGT 2013): the
// test never misses a bound that the exact ray touches.
//  - Principal slabs: n · o and n · d are the ray's own coordinates (exact);
//    the only roundings are (bound - o) and the multiplication by 1/d, each
//    within half an ulp of its result, so widening each slab's parameters
//    by 2 gamma(3) of their magnitude keeps them outside the exact ones.
//  - Auxiliary slabs: the dot products are sums of four rounded terms, off
//    by at most gamma(4) sum |n_i o_i| (and likewise for d); over the
//    parameter range [s_min, s_max] the event's computed dot product is off
//    by at most e = err_o + max(|s_min|, |s_max|) err_d, so each slab is
//    widened by e before the same test. With an infinite range, the
//    auxiliary slabs are skipped (the principal ones still cull).
//  - A direction component of exactly zero is a ray parallel to the slab:
//    inside or out for all s, never a division by zero.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "runtime/bounds/slab_bound.hpp"
#include "runtime/geometry/spacetime.hpp"

namespace hexant::runtime {

namespace slab_ray_detail {

inline constexpr double kEpsilon = std::numeric_limits<double>::epsilon() * 0.5;  // unit roundoff

constexpr double gamma(int n) {
    return n * kEpsilon / (1.0 - n * kEpsilon);
}

// Widening of the parameters: the subtraction and the multiplication by the
// rounded reciprocal (three roundings) stay within gamma(3) relative; twice
// that is Ize's margin, and one more ulp covers the widening's own rounding.
inline constexpr double kParameterMargin = 2.0 * gamma(3) + 2.0 * kEpsilon;

}  // namespace slab_ray_detail

class SlabRay {
  public:
    explicit SlabRay(const Ray4& ray);

    // Whether the ray meets the bound for some s in [s_min, s_max]; if so,
    // enter and exit (when not null) receive the parameter range inside the
    // bound, clipped to [s_min, s_max] and possibly a little wider than the
    // exact one, never narrower.
    bool intersect(const SlabBound& bound, double s_min, double s_max, double* enter = nullptr,
                   double* exit = nullptr) const;

    // The same for a 4D box (a hierarchy cell): only the principal slabs,
    // whose dot products are exact, with the same widening. A ray at one
    // instant meets only boxes whose time range holds that instant.
    bool clip(const Box4& box, double s_min, double s_max, double* enter = nullptr,
              double* exit = nullptr) const;

    const Ray4& ray() const { return ray_; }

  private:
    Ray4 ray_;
    std::array<double, kSlabCount> origin_dot_;    // n · o
    std::array<double, kSlabCount> inverse_dot_;   // 1 / (n · d); inf when n · d = 0
    std::array<bool, kSlabCount> parallel_;        // n · d == 0
    std::array<double, kSlabCount> origin_error_;  // bound of |computed - exact| n · o
    std::array<double, kSlabCount> direction_error_;
};

// Inline: the hierarchy's walk clips every child it might enter.
inline bool SlabRay::clip(const Box4& box, double s_min, double s_max, double* enter,
                          double* exit) const {
    double near = s_min, far = s_max;
    if (!(near <= far)) return false;
    // Time first: a ray at one instant leaves half of a cell's children at
    // once, before any division.
    for (const int k : {3, 0, 1, 2}) {
        const double lo = box.lo[k], hi = box.hi[k];
        if (!(lo <= hi)) return false;
        if (parallel_[k]) {
            if (origin_dot_[k] < lo || origin_dot_[k] > hi) return false;
            continue;
        }
        double a = (lo - origin_dot_[k]) * inverse_dot_[k];
        double b = (hi - origin_dot_[k]) * inverse_dot_[k];
        if (a > b) std::swap(a, b);
        a -= std::fabs(a) * slab_ray_detail::kParameterMargin;
        b += std::fabs(b) * slab_ray_detail::kParameterMargin;
        if (a != a || b != b) continue;
        near = std::max(near, a);
        far = std::min(far, b);
        if (near > far) return false;
    }
    if (enter) *enter = near;
    if (exit) *exit = far;
    return true;
}

}  // namespace hexant::runtime
