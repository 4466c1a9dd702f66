// Barr's global deformations ("Global and Local Deformations of Solid
// Primitives", SIGGRAPH 1984): twist, taper and bend about an axis through
// the origin of the object's local frame, each with its forward map (object
// to world) and its inverse, generic over the number type (double for
// intersection, Interval for bounds, Dual for root finding), and the forward
// Jacobian for doubles (for normals).
//
// Every map works in the deformation's frame (axis â, spine ŝ, cross ĉ =
// â × ŝ) on the local coordinates a = p·â, s = p·ŝ, c = p·ĉ:
//   twist  a' = a, (s', c') = (s, c) rotated by k a about â, k = amount in
//          degrees per unit length along â;
//   taper  a' = a, (s', c') = (1 + m a) (s, c), m = amount per unit length;
//   bend   the axis bends towards +ŝ into a circular arc of radius 1/k, k =
//          amount in degrees per unit length; θ = k a,
//          a' = a S(θ) - s sinθ,  s' = s cosθ + a C(θ),  c' = c,
//          with S(θ) = sinθ/θ and C(θ) = (1 - cosθ)/θ, so that k = 0 is the
//          identity without a division by k.
// The spine ŝ is the unit part of +y perpendicular to â, or of +z when â is
// within about 1e-3 of ±y. For twist and taper its choice does not matter.
//
// Where the maps are one to one:
//   twist  everywhere;
//   taper  where 1 + m a > 0 (a factor below 0 mirrors the section, and the
//          inverse still undoes it; at |1 + m a| < kMinTaperFactor the
//          inverse divides by ±kMinTaperFactor instead, so it stays finite);
//   bend   where 1 - k s > 0 (the near side of the centre of curvature) and
//          |θ| < π (the object bends less than half a turn). Elsewhere the
//          inverse returns some other preimage, always finite.
// Interval results enclose the exact values and the double evaluator's
// results at every point of the arguments: the interval code repeats the
// double code's operations in the same order (the only exceptions, S(θ) and
// the branches, are bounded explicitly below).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "runtime/time/dual.hpp"
#include "runtime/time/interval.hpp"

namespace hexant::runtime {

namespace deformation_detail {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kDegree = kPi / 180.0;
// Below this, the series of S is exact to double precision (x^6/5040 is
// under 1e-27) and avoids 0/0.
inline constexpr double kSincSeries = 1e-4;
// Below this, the series of S' avoids the cancellation in (x cos x - sin x).
inline constexpr double kSincDerivativeSeries = 0.05;
// A lower bound of S over all reals (its minimum, -0.2172336..., at x = 4.4934...).
inline constexpr double kSincMinimum = -0.21724;
// |sin x / x| is off by at most 1 ulp (libm) + 0.5 ulp (division) from the
// exact value; stepping bounds this many ulps outward covers that at both
// ends of an interval.
inline constexpr int kSincUlps = interval_detail::kLibmUlps + 2;
// A spine from +y needs â at least this far from ±y (squared perpendicular
// part, about (1e-3)^2): below it the perpendicular part of y is too short to
// normalise without losing digits, and +z is used instead.
inline constexpr double kNearYSquared = 1e-6;
// Unbend divides by rho S(θ) while it exceeds this (far from the centre of
// curvature and from half a turn); beyond it, by k, which is then not small.
inline constexpr double kUnbendDivisor = 0.125;

// Results of the double inverses for finite input: overflow is clamped (the
// tracer must never see Inf).
inline double keep_finite(double x) {
    constexpr double m = std::numeric_limits<double>::max();
    return x > m ? m : (x < -m ? -m : x);
}
inline Dual keep_finite(const Dual& x) {
    return {keep_finite(x.v), x.d};
}
inline Interval keep_finite(const Interval& x) {
    return x;  // an interval may have infinite ends; it bounds the clamped values too
}

// A frame component is a unit vector's coordinate: never outside [-1, 1].
inline double clamp_unit(double x) {
    return x;
}
inline Dual clamp_unit(const Dual& x) {
    return x;
}
inline Interval clamp_unit(const Interval& x) {
    const Interval r{std::max(x.lo, -1.0), std::min(x.hi, 1.0)};
    return r.is_empty() ? Interval{-1.0, 1.0} : r;
}

}  // namespace deformation_detail

// S(x) = sin(x) / x, S(0) = 1.
inline double sinc(double x) {
    using namespace deformation_detail;
    if (std::fabs(x) < kSincSeries) {
        const double x2 = x * x;
        return 1.0 - x2 / 6.0 * (1.0 - x2 / 20.0);
    }
    return std::sin(x) / x;
}

// S'(x) = (x cos x - sin x) / x^2.
inline double sinc_derivative(double x) {
    using namespace deformation_detail;
    if (std::fabs(x) < kSincDerivativeSeries) {
        const double x2 = x * x;
        return x * (-1.0 / 3.0 + x2 * (1.0 / 30.0 - x2 * (1.0 / 840.0 - x2 / 45360.0)));
    }
    return (x * std::cos(x) - std::sin(x)) / (x * x);
}

inline Dual sinc(const Dual& x) {
    return {sinc(x.v), sinc_derivative(x.v) * x.d};
}

// S is even and falls on [0, π]; beyond, it lies in [kSincMinimum, 1] and
// within ±1/|x|.
inline Interval sinc(const Interval& x) {
    using namespace deformation_detail;
    using interval_detail::down;
    using interval_detail::up;
    const double near = x.mignitude();
    const double far = x.magnitude();
    const double hi = near <= kPi ? up(sinc(near), kSincUlps) : up(1.0 / near, 2);
    double lo = far <= kPi ? down(sinc(far), kSincUlps) : kSincMinimum;
    if (near > kPi) lo = std::max(lo, -up(1.0 / near, 2));
    return {lo, hi};
}

// C(x) = (1 - cos x) / x = sin(x/2) S(x/2), free of cancellation near 0.
template <class N>
N cosc(const N& x) {
    using std::sin;
    const N h = x * N(0.5);
    return sin(h) * sinc(h);
}

// The deformation's orthonormal frame: axis â, spine ŝ, cross ĉ = â × ŝ.
template <class N>
struct DeformationFrame {
    std::array<N, 3> axis, spine, cross;
};

namespace deformation_detail {

template <class N>
N dot(const std::array<N, 3>& a, const std::array<N, 3>& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// The frame for a unit axis and the principal direction `reference` (1 = y,
// 2 = z), by Gram-Schmidt twice (the second pass restores orthogonality to
// rounding when â is close to the reference).
template <class N>
DeformationFrame<N> frame_from(const std::array<N, 3>& axis, int reference) {
    using std::sqrt;
    DeformationFrame<N> f;
    f.axis = axis;
    std::array<N, 3> u;
    for (int i = 0; i < 3; ++i) u[i] = N(i == reference ? 1.0 : 0.0) - axis[reference] * axis[i];
    for (int pass = 0; pass < 2; ++pass) {
        if (pass == 1) {
            const N d = dot(u, axis);
            for (int i = 0; i < 3; ++i) u[i] = u[i] - d * axis[i];
        }
        const N length = sqrt(dot(u, u));
        for (int i = 0; i < 3; ++i) u[i] = clamp_unit(u[i] / length);
    }
    f.spine = u;
    f.cross = {clamp_unit(axis[1] * u[2] - axis[2] * u[1]),
               clamp_unit(axis[2] * u[0] - axis[0] * u[2]),
               clamp_unit(axis[0] * u[1] - axis[1] * u[0])};
    return f;
}

template <class N>
DeformationFrame<N> hull(const DeformationFrame<N>& a, const DeformationFrame<N>& b) {
    DeformationFrame<N> r;
    for (int i = 0; i < 3; ++i) {
        r.axis[i] = hull(a.axis[i], b.axis[i]);
        r.spine[i] = hull(a.spine[i], b.spine[i]);
        r.cross[i] = hull(a.cross[i], b.cross[i]);
    }
    return r;
}

inline double value_of(double x) {
    return x;
}
inline double value_of(const Dual& x) {
    return x.v;
}

}  // namespace deformation_detail

// The frame for an axis direction of any length; a zero or non-finite
// direction gives the frame of +y (a degenerate scene must not give NaN).
template <class N>
DeformationFrame<N> deformation_frame(const std::array<N, 3>& direction) {
    using namespace deformation_detail;
    using std::sqrt;
    const N length = sqrt(dot(direction, direction));
    if constexpr (std::is_same_v<N, Interval>) {
        if (!(length.lo > 0.0) || !std::isfinite(length.hi)) {
            const Interval u{-1.0, 1.0};
            return {{u, u, u}, {u, u, u}, {u, u, u}};
        }
        std::array<N, 3> a;
        for (int i = 0; i < 3; ++i) a[i] = clamp_unit(direction[i] / length);
        const Interval perp = a[0] * a[0] + a[2] * a[2];
        if (perp.lo >= kNearYSquared) return frame_from(a, 1);
        if (perp.hi < kNearYSquared) return frame_from(a, 2);
        return hull(frame_from(a, 1), frame_from(a, 2));
    } else {
        const double l = value_of(length);
        if (!(l > 0.0) || !std::isfinite(l)) return frame_from<N>({N(0.0), N(1.0), N(0.0)}, 2);
        std::array<N, 3> a;
        for (int i = 0; i < 3; ++i) a[i] = direction[i] / length;
        const double perp = value_of(a[0] * a[0] + a[2] * a[2]);
        return frame_from(a, perp >= kNearYSquared ? 1 : 2);
    }
}

inline DeformationFrame<double> deformation_frame(const glm::dvec3& direction) {
    return deformation_frame(std::array<double, 3>{direction.x, direction.y, direction.z});
}

// Local coordinates (a, s, c) of a point, and back. The frame's number type
// M is N itself or double.
template <class N, class M>
std::array<N, 3> to_local(const std::array<N, 3>& p, const DeformationFrame<M>& f) {
    std::array<N, 3> q;
    const std::array<M, 3>* rows[3] = {&f.axis, &f.spine, &f.cross};
    for (int i = 0; i < 3; ++i)
        q[i] = p[0] * N((*rows[i])[0]) + p[1] * N((*rows[i])[1]) + p[2] * N((*rows[i])[2]);
    return q;
}

template <class N, class M>
std::array<N, 3> from_local(const std::array<N, 3>& q, const DeformationFrame<M>& f) {
    std::array<N, 3> p;
    for (int i = 0; i < 3; ++i)
        p[i] = q[0] * N(f.axis[i]) + q[1] * N(f.spine[i]) + q[2] * N(f.cross[i]);
    return p;
}

// Frames are most often axis-aligned: their zero products are skipped.
inline std::array<Interval, 3> to_local(const std::array<Interval, 3>& p,
                                        const DeformationFrame<double>& f) {
    return {sparse_dot(f.axis[0], f.axis[1], f.axis[2], p),
            sparse_dot(f.spine[0], f.spine[1], f.spine[2], p),
            sparse_dot(f.cross[0], f.cross[1], f.cross[2], p)};
}

inline std::array<Interval, 3> from_local(const std::array<Interval, 3>& q,
                                          const DeformationFrame<double>& f) {
    std::array<Interval, 3> p;
    for (int i = 0; i < 3; ++i) p[i] = sparse_dot(f.axis[i], f.spine[i], f.cross[i], q);
    return p;
}

// The maps in local coordinates (a, s, c).

template <class N>
std::array<N, 3> twist_local(const std::array<N, 3>& q, const N& degrees_per_unit) {
    using std::cos;
    using std::sin;
    const N angle = degrees_per_unit * N(deformation_detail::kDegree) * q[0];
    const N cs = cos(angle), sn = sin(angle);
    return {q[0], q[1] * cs - q[2] * sn, q[1] * sn + q[2] * cs};
}

// The twist leaves a unchanged, so the same angle undoes it.
template <class N>
std::array<N, 3> untwist_local(const std::array<N, 3>& q, const N& degrees_per_unit) {
    using std::cos;
    using std::sin;
    const N angle = degrees_per_unit * N(deformation_detail::kDegree) * q[0];
    const N cs = cos(angle), sn = sin(angle);
    return {q[0], q[1] * cs + q[2] * sn, q[2] * cs - q[1] * sn};
}

namespace deformation_detail {

// The double rotation's |result| exceeds the exact radius by the sine's and
// cosine's errors (kLibmUlps each) and the rounding of two products and a
// sum; this many ulps of the radius cover all of it with room to spare.
inline constexpr int kRotationUlps = 4 * interval_detail::kLibmUlps + 16;

// The distances from the axis of the points of a box in local coordinates
// (a, s, c): sqrt(s^2 + c^2) over the box, rounded outward.
inline Interval section_radius(const std::array<Interval, 3>& q) {
    using interval_detail::next_down;
    using interval_detail::next_up;
    const double s_far = q[1].magnitude(), c_far = q[2].magnitude();
    const double s_near = q[1].mignitude(), c_near = q[2].mignitude();
    const double far = next_up(std::sqrt(next_up(next_up(s_far * s_far) + next_up(c_far * c_far))));
    const double near =
        next_down(std::sqrt(next_down(next_down(s_near * s_near) + next_down(c_near * c_near))));
    return {std::max(0.0, near), far};
}

// A rotation keeps each point's distance from the axis, so the turned
// section lies within [-r, r] on both section axes, r the largest distance
// over the box. The interval products treat the angle and the point as
// independent and lose that: an arc's box comes out up to sqrt(2) wider
// than its radius, and a stiff twist's pieces would meet a surface they
// never come near. Cutting to the radius keeps the enclosure and restores it.
inline std::array<Interval, 3> within_radius(const std::array<Interval, 3>& turned,
                                             const std::array<Interval, 3>& q) {
    using interval_detail::next_up;
    constexpr double kGrowth = 1.0 + (kRotationUlps + 4) * 0x1p-52;
    // One multiplication by (1 + n ulps), rounded up, in place of n steps.
    const double r = next_up(section_radius(q).hi * kGrowth);
    if (!std::isfinite(r)) return turned;
    const Interval disc{-r, r};
    const Interval s2 = intersect(turned[1], disc), c2 = intersect(turned[2], disc);
    return {turned[0], s2.is_empty() ? turned[1] : s2, c2.is_empty() ? turned[2] : c2};
}

}  // namespace deformation_detail

inline std::array<Interval, 3> twist_local(const std::array<Interval, 3>& q,
                                           const Interval& degrees_per_unit) {
    return deformation_detail::within_radius(twist_local<Interval>(q, degrees_per_unit), q);
}

inline std::array<Interval, 3> untwist_local(const std::array<Interval, 3>& q,
                                             const Interval& degrees_per_unit) {
    return deformation_detail::within_radius(untwist_local<Interval>(q, degrees_per_unit), q);
}

template <class N>
std::array<N, 3> taper_local(const std::array<N, 3>& q, const N& factor_per_unit) {
    const N f = N(1.0) + factor_per_unit * q[0];
    return {q[0], q[1] * f, q[2] * f};
}

// The inverse taper's factor is a pure number (amount x length), so its
// floor may be a fixed constant without depending on the scene's scale.
inline constexpr double kMinTaperFactor = 1e-12;

namespace deformation_detail {

inline double divide_by_factor(double x, double f) {
    if (std::fabs(f) < kMinTaperFactor) f = f < 0.0 ? -kMinTaperFactor : kMinTaperFactor;
    return keep_finite(x / f);
}
inline Dual divide_by_factor(const Dual& x, const Dual& f) {
    if (std::fabs(f.v) < kMinTaperFactor)
        return keep_finite(x / Dual(f.v < 0.0 ? -kMinTaperFactor : kMinTaperFactor));
    return keep_finite(x / f);
}
// The double code divides by f moved out of (-kMin, kMin): by
// max(f, kMin) where f >= 0 and by min(f, -kMin) where f < 0.
inline Interval divide_by_factor(const Interval& x, const Interval& f) {
    if (f.lo >= kMinTaperFactor || f.hi <= -kMinTaperFactor) return x / f;
    Interval r{interval_detail::kInf, -interval_detail::kInf};  // empty
    if (f.hi >= 0.0)
        r = hull(r, x / Interval(std::max(std::max(f.lo, 0.0), kMinTaperFactor),
                                 std::max(f.hi, kMinTaperFactor)));
    if (f.lo < 0.0)
        r = hull(r,
                 x / Interval(std::min(f.lo, -kMinTaperFactor), std::min(f.hi, -kMinTaperFactor)));
    return r;
}

}  // namespace deformation_detail

template <class N>
std::array<N, 3> untaper_local(const std::array<N, 3>& q, const N& factor_per_unit) {
    using deformation_detail::divide_by_factor;
    const N f = N(1.0) + factor_per_unit * q[0];
    return {q[0], divide_by_factor(q[1], f), divide_by_factor(q[2], f)};
}

template <class N>
std::array<N, 3> bend_local(const std::array<N, 3>& q, const N& degrees_per_unit) {
    using std::cos;
    using std::sin;
    const N theta = degrees_per_unit * N(deformation_detail::kDegree) * q[0];
    const N sn = sin(theta), cs = cos(theta);
    return {q[0] * sinc(theta) - q[1] * sn, q[1] * cs + q[0] * cosc(theta), q[2]};
}

// From a' = sinθ (1/k - s) and 1/k - s' = cosθ (1/k - s):
//   rho = 1 - k s = |(k a', 1 - k s')|, θ = atan2(k a', 1 - k s'),
//   s = (1 - rho) / k = (2 s' - k (a'^2 + s'^2)) / (1 + rho),
//   a = θ / k = a' / (rho S(θ)),
// the last form free of k while rho S(θ) is not small.
namespace deformation_detail {

// The bend's angle atan2(ka, d), with a zero ka always +0: beyond the centre
// of curvature (d < 0) the angle jumps from pi to -pi across ka = 0, and a
// path lying exactly in that plane (a ray in the plane of a bent object's
// end) must not straddle the jump on the sign of a zero, or every piece of
// it would span both branches and be refined to single ulps.
inline double bend_angle(double ka, double d) {
    return std::atan2(ka + 0.0, d);  // -0 + 0 is +0
}
inline Dual bend_angle(const Dual& ka, const Dual& d) {
    using std::atan2;
    return atan2(Dual(ka.v + 0.0, ka.d), d);
}
// On ka >= 0 (zero read as +0) the angle is continuous off the origin, so
// its extremes lie at corners even where the box touches the cut.
inline Interval bend_angle(const Interval& ka, const Interval& d) {
    using interval_detail::down;
    using interval_detail::up;
    if (!(ka.lo == 0.0 && d.hi < 0.0)) return atan2(ka, d);
    const double a1 = std::atan2(0.0, d.lo), a2 = std::atan2(0.0, d.hi);
    const double a3 = std::atan2(ka.hi, d.lo), a4 = std::atan2(ka.hi, d.hi);
    const double lo = std::min(std::min(a1, a2), std::min(a3, a4));
    const double hi = std::max(std::max(a1, a2), std::max(a3, a4));
    return {std::max(0.0, down(lo, interval_detail::kLibmUlps)),
            std::min(interval_detail::next_up(kPi), up(hi, interval_detail::kLibmUlps))};
}

}  // namespace deformation_detail

template <class N>
std::array<N, 3> unbend_local(const std::array<N, 3>& q, const N& degrees_per_unit) {
    using namespace deformation_detail;
    using std::atan2;
    using std::sqrt;
    const N k = degrees_per_unit * N(kDegree);
    const N ka = k * q[0];
    const N d = N(1.0) - k * q[1];
    const N rho = sqrt(ka * ka + d * d);
    const N theta = deformation_detail::bend_angle(ka, d);
    const N s = (N(2.0) * q[1] - k * (q[0] * q[0] + q[1] * q[1])) / (N(1.0) + rho);
    const N divisor = rho * sinc(theta);
    N a;
    if constexpr (std::is_same_v<N, Interval>) {
        if (divisor.lo > kUnbendDivisor) {
            a = q[0] / divisor;
        } else if (divisor.hi <= kUnbendDivisor) {
            a = theta / k;
        } else {
            a = hull(q[0] / Interval(kUnbendDivisor, divisor.hi), theta / k);
        }
    } else {
        a = value_of(divisor) > kUnbendDivisor ? q[0] / divisor : theta / k;
    }
    return {keep_finite(a), keep_finite(s), q[2]};
}

// The maps on points of the object's frame.

template <class N, class M>
std::array<N, 3> twist(const std::array<N, 3>& p, const DeformationFrame<M>& f, const N& amount) {
    return from_local(twist_local(to_local(p, f), amount), f);
}
template <class N, class M>
std::array<N, 3> untwist(const std::array<N, 3>& p, const DeformationFrame<M>& f, const N& amount) {
    return from_local(untwist_local(to_local(p, f), amount), f);
}
template <class N, class M>
std::array<N, 3> taper(const std::array<N, 3>& p, const DeformationFrame<M>& f, const N& amount) {
    return from_local(taper_local(to_local(p, f), amount), f);
}
template <class N, class M>
std::array<N, 3> untaper(const std::array<N, 3>& p, const DeformationFrame<M>& f, const N& amount) {
    return from_local(untaper_local(to_local(p, f), amount), f);
}
template <class N, class M>
std::array<N, 3> bend(const std::array<N, 3>& p, const DeformationFrame<M>& f, const N& amount) {
    return from_local(bend_local(to_local(p, f), amount), f);
}
template <class N, class M>
std::array<N, 3> unbend(const std::array<N, 3>& p, const DeformationFrame<M>& f, const N& amount) {
    return from_local(unbend_local(to_local(p, f), amount), f);
}

// Forward Jacobians d(deformed)/d(point) at an undeformed point, in the
// object's frame: F J_local F^T with F = [â ŝ ĉ].
glm::dmat3 twist_jacobian(const glm::dvec3& p, const DeformationFrame<double>& f, double amount);
glm::dmat3 taper_jacobian(const glm::dvec3& p, const DeformationFrame<double>& f, double amount);
glm::dmat3 bend_jacobian(const glm::dvec3& p, const DeformationFrame<double>& f, double amount);

}  // namespace hexant::runtime
