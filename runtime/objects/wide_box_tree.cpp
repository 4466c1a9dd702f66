#include "runtime/objects/wide_box_tree.hpp"

#include <cfloat>
#include <cmath>
#include <limits>

#include "runtime/geometry/float_rounding.hpp"
#include "runtime/objects/box_hierarchy.hpp"

namespace hexant::runtime::objects {

namespace {

// Four floats as one register: the compiler's vector extension (SSE on
// x86-64, NEON on ARM, four scalar operations elsewhere).
using F4 = float __attribute__((vector_size(16)));
using I4 = std::int32_t __attribute__((vector_size(16)));

F4 all(float f) {
    return F4{f, f, f, f};
}

F4 load(const float* p) {
    F4 v;
    __builtin_memcpy(&v, p, sizeof v);
    return v;
}

constexpr double kRange = 0x1p100;
constexpr float kWidening = 0x1p-20f;

}  // namespace

bool WideRay::prepare(const geometry::Ray3& ray) {
    parallel = 0;
    double largest = 0.0;
    for (int j = 0; j < 3; ++j) {
        const double o = ray.origin[j], d = ray.direction[j];
        if (!(std::fabs(o) < kRange) || !(std::fabs(d) < kRange)) return false;
        const double error = 0x1p-23 * std::fabs(o);  // the rounding to float, with room
        origin[j] = static_cast<float>(o);
        if (d == 0.0) {
            parallel |= std::uint8_t(1u << j);
            inverse[j] = 0.0f;
            negative[j] = false;
            slack[j] = geometry::float_up(2.0 * error + std::numeric_limits<double>::denorm_min());
            continue;
        }
        const double inv = 1.0 / d;
        if (!(std::fabs(inv) < kRange)) return false;
        inverse[j] = static_cast<float>(inv);
        negative[j] = d < 0.0;
        slack[j] = 0.0f;
        largest = std::max(largest, error * std::fabs(inv) * (1.0 + 0x1p-20));
    }
    // Rounded up by the factor: the conversion to float loses at most
    // 2^-24 of it.
    epsilon = static_cast<float>(2.0 * largest * (1.0 + 0x1p-20)) + FLT_MIN;
    return std::isfinite(epsilon);
}

float WideBoxTree::up(double s) {
    return geometry::float_up(s);
}

unsigned WideBoxTree::meets(const Node& node, const WideRay& r, float s_min, float s_max,
                            float* enter) {
    F4 near = all(s_min), far = all(s_max);
    I4 inside = I4{-1, -1, -1, -1};
    for (int j = 0; j < 3; ++j) {
        const F4 lo = load(node.lo[j]), hi = load(node.hi[j]);
        const F4 o = all(r.origin[j]);
        if ((r.parallel >> j) & 1) {
            const F4 slack = all(r.slack[j]);
            inside &= (lo - slack <= o) & (o <= hi + slack);
            continue;
        }
        // The end met first by the direction's sign: an empty slot
        // (lo = +inf, hi = -inf) then enters at +inf and is never met.
        const F4 inv = all(r.inverse[j]);
        const F4 first = r.negative[j] ? hi : lo;
        const F4 last = r.negative[j] ? lo : hi;
        const F4 a = (first - o) * inv, b = (last - o) * inv;
        near = a > near ? a : near;
        far = b < far ? b : far;
    }
    // Infinities to the float range, then the widening: never NaN.
    const F4 big = all(FLT_MAX);
    near = near < big ? near : big;
    far = far > -big ? far : -big;
    const F4 eps = all(r.epsilon), widening = all(kWidening);
    const F4 zero = all(0.0f);
    near = near - ((near < zero ? -near : near) * widening + eps);
    far = far + ((far < zero ? -far : far) * widening + eps);
    const I4 hit = inside & (near <= far);
    __builtin_memcpy(enter, &near, sizeof near);
    unsigned mask = 0;
    for (int k = 0; k < kWideWidth; ++k) mask |= unsigned(hit[k] != 0) << k;
    return mask;
}

unsigned WideBoxTree::meets_double(const Node& node, const geometry::Ray3& ray,
                                   const glm::dvec3& inverse, double s_min, double s_max,
                                   double* enter) {
    unsigned mask = 0;
    for (int k = 0; k < kWideWidth; ++k) {
        const geometry::Box3 box{{node.lo[0][k], node.lo[1][k], node.lo[2][k]},
                                 {node.hi[0][k], node.hi[1][k], node.hi[2][k]}};
        // (An empty slot: ray_meets_box would read its swapped ends as all space.)
        if (!(box.lo.x <= box.hi.x)) continue;
        if (ray_meets_box(box, ray.origin, inverse, s_min, s_max, enter[k])) mask |= 1u << k;
    }
    return mask;
}

}  // namespace hexant::runtime::objects
