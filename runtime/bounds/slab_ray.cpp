#include "runtime/bounds/slab_ray.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hexant::runtime {

namespace {

using slab_ray_detail::gamma;
using slab_ray_detail::kEpsilon;
using slab_ray_detail::kParameterMargin;

}  // namespace

SlabRay::SlabRay(const Ray4& ray) : ray_(ray) {
    const auto& normals = slab_normals();
    for (int k = 0; k < kSlabCount; ++k) {
        const Event& n = normals[k];
        double o = 0.0, d = 0.0, mo = 0.0, md = 0.0;
        for (int i = 0; i < 4; ++i) {
            o += n[i] * ray.origin[i];
            d += n[i] * ray.direction[i];
            mo += std::fabs(n[i] * ray.origin[i]);
            md += std::fabs(n[i] * ray.direction[i]);
        }
        origin_dot_[k] = o;
        parallel_[k] = d == 0.0;
        inverse_dot_[k] = parallel_[k] ? 0.0 : 1.0 / d;
        // Principal slabs take a coordinate as it is; the sums of the
        // auxiliary ones are off by at most gamma(4) of the sum of
        // magnitudes (rounded up by a further factor).
        const double g = k < 4 ? 0.0 : gamma(5);
        origin_error_[k] = g * mo;
        direction_error_[k] = g * md;
    }
}

bool SlabRay::intersect(const SlabBound& bound, double s_min, double s_max, double* enter,
                        double* exit) const {
    double near = s_min, far = s_max;
    if (!(near <= far)) return false;
    const double reach = std::max(std::fabs(s_min), std::fabs(s_max));
    const bool finite_range = std::isfinite(reach);
    for (int k = 0; k < kSlabCount; ++k) {
        double widen = 0.0;
        if (k >= 4) {
            if (!finite_range) continue;
            widen = (origin_error_[k] + reach * direction_error_[k]) * (1.0 + 4.0 * kEpsilon);
            if (!std::isfinite(widen)) continue;
        }
        const double lo = bound.lo[k] - widen, hi = bound.hi[k] + widen;
        if (!(lo <= hi)) return false;
        if (parallel_[k]) {
            // n · (o + s d) = n · o for all s, within origin_error_ (in widen).
            if (origin_dot_[k] < lo || origin_dot_[k] > hi) return false;
            continue;
        }
        double a = (lo - origin_dot_[k]) * inverse_dot_[k];
        double b = (hi - origin_dot_[k]) * inverse_dot_[k];
        if (a > b) std::swap(a, b);
        // An infinite slab end gives an infinite parameter, which is right;
        // inf - inf cannot occur since lo and hi are not both infinite the
        // same way in a non-empty bound.
        a -= std::fabs(a) * kParameterMargin;
        b += std::fabs(b) * kParameterMargin;
        if (a != a || b != b) continue;  // a slab that says nothing
        near = std::max(near, a);
        far = std::min(far, b);
        if (near > far) return false;
    }
    if (enter) *enter = near;
    if (exit) *exit = far;
    return true;
}

}  // namespace hexant::runtime
