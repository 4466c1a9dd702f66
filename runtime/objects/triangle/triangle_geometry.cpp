#include "runtime/objects/triangle/triangle_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "runtime/geometry/box_queries.hpp"
#include "runtime/geometry/stable_arithmetic.hpp"

namespace hexant::runtime::geometry {

namespace {

// t in double is used when its error bound is below this part of it.
constexpr double kRefineBelow = 0x1p24;

// The bound on the error of t = sum e_i z_i / sum e_i from the sheared
// coordinates' magnitudes, for arithmetic whose every step errs by at most
// gamma(n) of its operands' magnitudes (the argument is in
// intersect_barycentric, below).
template <class Gamma>
double parameter_error(Gamma gamma, double max_x, double max_y, double max_z, double spread_z,
                       double sum_e, double det) {
    const double delta_x = gamma(5) * (max_x + max_z);
    const double delta_y = gamma(5) * (max_y + max_z);
    const double delta_e = 2.0 * (gamma(2) * max_x * max_y + delta_y * max_x + delta_x * max_y);
    return 2.0 * (2.0 * gamma(3) * max_z * sum_e + 3.0 * delta_e * spread_z) / std::fabs(det);
}

// gamma(n) for double-double arithmetic (stable_arithmetic.hpp): each of its
// sums and products errs by at most about 8 u^2 of its operands' magnitudes
// (Joldes, Muller and Popescu 2017, for the sloppy sum and the product
// without the low parts' product), u = 2^-53; taken as 2^-100, eight times
// that, for the margin.
double double_double_gamma(int n) {
    constexpr double u = 0x1p-100;
    return n * u / (1.0 - n * u);
}

DoubleDouble dd(double x) {
    return {x, 0.0};
}

DoubleDouble operator-(const DoubleDouble& a, const DoubleDouble& b) {
    return a + (-b);
}

// t in the sheared frame, formed again in double-double, when t in double
// lies within its own error bound of zero and its sign is not known. This
// happens where the triangle is far larger than the hit's distance (a floor
// with vertices at 1e15 seen from a few units: t's terms are 1e15 and its
// value 5). Returns t and its error bound if t is known to be positive and
// the ray crosses the triangle by these coordinates, else nothing.
struct RefinedParameter {
    double t, error;
};
[[gnu::noinline]] std::optional<RefinedParameter> refined_parameter(
    const glm::dvec3& p1, const glm::dvec3& p2, const glm::dvec3& p3, const glm::dvec3& origin,
    int kx, int ky, int kz, double sx, double sy, double sz) {
    struct Sheared {
        DoubleDouble x, y, z;
    };
    // p - origin exactly (two-sum), then the shear with the same factors as
    // in double, so that it is the same linear map.
    const auto shear = [&](const glm::dvec3& p) {
        const DoubleDouble a[3] = {two_sum(p.x, -origin.x), two_sum(p.y, -origin.y),
                                   two_sum(p.z, -origin.z)};
        return Sheared{a[kx] - dd(sx) * a[kz], a[ky] - dd(sy) * a[kz], dd(sz) * a[kz]};
    };
    const Sheared a = shear(p1), b = shear(p2), c = shear(p3);
    const DoubleDouble eu = c.x * b.y - c.y * b.x;
    const DoubleDouble ev = a.x * c.y - a.y * c.x;
    const DoubleDouble ew = b.x * a.y - b.y * a.x;
    // The ray's crossing inside the triangle, decided again from these
    // coordinates: in double their rounding (ulps of the vertices) moves
    // the edges by units at 1e18, which drew such a triangle far beyond its
    // edges. Each edge function depends only on its edge's two vertices and
    // is formed with the same operations by both triangles sharing it (or
    // their negation, which may differ in the low part's last bits: the
    // sign differs only where the value is within those of zero).
    const double u = eu.value(), v = ev.value(), w = ew.value();
    if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return std::nullopt;
    const double det = (eu + ev + ew).value();
    if (det == 0.0 || !std::isfinite(det)) return std::nullopt;
    const double t = (eu * a.z + ev * b.z + ew * c.z).value() / det;
    using std::fabs;
    const double az = a.z.value(), bz = b.z.value(), cz = c.z.value();
    const double max_z = std::max({fabs(az), fabs(bz), fabs(cz)});
    const double spread_z = std::max({az, bz, cz}) - std::min({az, bz, cz});
    const double max_x = std::max({fabs(a.x.value()), fabs(b.x.value()), fabs(c.x.value())});
    const double max_y = std::max({fabs(a.y.value()), fabs(b.y.value()), fabs(c.y.value())});
    const double sum_e = fabs(eu.value()) + fabs(ev.value()) + fabs(ew.value());
    // The bound in double-double's gamma, widened by a few ulps for the
    // three values read back into double and the division (relative to t,
    // as they round t itself), and for the magnitudes' own rounding.
    const double delta_t =
        (1.0 + rounding_gamma(8)) *
        parameter_error(double_double_gamma, max_x, max_y, max_z, spread_z, sum_e, det);
    const double error = delta_t + rounding_gamma(4) * std::fabs(t);
    if (!(t > error)) return std::nullopt;
    return RefinedParameter{t, error};
}

}  // namespace

std::optional<BarycentricHit> intersect_barycentric(const glm::dvec3& p1, const glm::dvec3& p2,
                                                    const glm::dvec3& p3, const Ray3& ray,
                                                    double s_min, double s_max) {
    const double scale_max = max_abs(ray.direction);
    if (!(scale_max > 0.0) || !std::isfinite(scale_max)) return std::nullopt;
    // Scale the direction by a power of two (exact) so that its largest
    // component lies in [0.5, 1): the shear factors below cannot overflow.
    int exponent = 0;
    std::frexp(scale_max, &exponent);
    const glm::dvec3 d{std::ldexp(ray.direction.x, -exponent),
                       std::ldexp(ray.direction.y, -exponent),
                       std::ldexp(ray.direction.z, -exponent)};
    // Shear and scale so the ray runs along +z from the origin.
    int kz = 0;
    if (std::fabs(d.y) > std::fabs(d[kz])) kz = 1;
    if (std::fabs(d.z) > std::fabs(d[kz])) kz = 2;
    int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    if (d[kz] < 0.0) std::swap(kx, ky);  // keeps the winding, hence the signs
    const double sx = d[kx] / d[kz], sy = d[ky] / d[kz], sz = 1.0 / d[kz];
    const glm::dvec3 a = p1 - ray.origin, b = p2 - ray.origin, c = p3 - ray.origin;
    const double ax = a[kx] - sx * a[kz], ay = a[ky] - sy * a[kz];
    const double bx = b[kx] - sx * b[kz], by = b[ky] - sy * b[kz];
    const double cx = c[kx] - sx * c[kz], cy = c[ky] - sy * c[kz];
    // Edge functions. Each depends only on its edge's two sheared vertices,
    // which both triangles sharing the edge compute identically, and its sign
    // is exact for them: a shared edge is never missed by both.
    const double eu = difference_of_products(cx, by, cy, bx);
    const double ev = difference_of_products(ax, cy, ay, cx);
    const double ew = difference_of_products(bx, ay, by, ax);
    if ((eu < 0.0 || ev < 0.0 || ew < 0.0) && (eu > 0.0 || ev > 0.0 || ew > 0.0)) {
        return std::nullopt;
    }
    const double det = eu + ev + ew;
    if (det == 0.0 || !std::isfinite(det)) return std::nullopt;
    const double az = sz * a[kz], bz = sz * b[kz], cz = sz * c[kz];
    const double t = (eu * az + ev * bz + ew * cz) / det;
    // A hit within t's own rounding error of the origin may be the surface
    // the ray leaves (a shadow ray from a floor whose vertices are far
    // larger than the step off it): its sign is not known, so it is no hit
    // (after pbrt-v4's Triangle::Intersect, "conservatively greater than
    // zero"). The bound: t = sum e_i z_i / sum e_i is the z's average by
    // the edge functions' weights, so an error de in each e_i moves t by at
    // most 3 de (spread of the z's) / |det| (t lies among the z's), and the
    // z's own rounding and the products' and sums' move it by gamma(3) of
    // the largest z each. de is pbrt's bound for the sheared coordinates'
    // products (the fused edge functions here round less). pbrt bounds the
    // weights' errors by the largest z instead of the spread, which rejects
    // a small triangle's honest hit from far away; the spread does not.
    // Twice the sum covers second-order terms.
    // A hit whose sign is not known in double but may be positive is
    // decided again in double-double (refined_parameter), and so is one
    // whose t is known only roughly.
    double t_known = t;
    double t_error = std::numeric_limits<double>::infinity();
    if (s_min >= 0.0) {
        using std::fabs;
        const double max_z = std::max({fabs(az), fabs(bz), fabs(cz)});
        const double spread_z = std::max({az, bz, cz}) - std::min({az, bz, cz});
        const double max_x = std::max({fabs(ax), fabs(bx), fabs(cx)});
        const double max_y = std::max({fabs(ay), fabs(by), fabs(cy)});
        const double sum_e = fabs(eu) + fabs(ev) + fabs(ew);
        const double delta_t =
            parameter_error(rounding_gamma, max_x, max_y, max_z, spread_z, sum_e, det);
        // Refined too where t is positive but known to worse than 2^-24 of
        // itself (a floor at 1e12 seen from a few units): double-double puts
        // the hit where it is, not a part of a unit off.
        t_error = delta_t;
        if (!(t > kRefineBelow * delta_t)) {
            if (!(t > -delta_t) || !(std::ldexp(t + delta_t, -exponent) > s_min) ||
                !(std::ldexp(t - delta_t, -exponent) < s_max)) {
                return std::nullopt;
            }
            const auto refined = refined_parameter(p1, p2, p3, ray.origin, kx, ky, kz, sx, sy, sz);
            if (!refined) return std::nullopt;
            t_known = refined->t;
            t_error = refined->error;
        }
    }
    const double s = std::ldexp(t_known, -exponent);
    if (!(s > s_min && s < s_max)) return std::nullopt;
    const double inv = 1.0 / det;
    return BarycentricHit{s, eu * inv, ev * inv, ew * inv, std::ldexp(t_error, -exponent)};
}

std::optional<SurfaceHit> intersect(const TriangleGeometry& triangle, const Ray3& ray, double s_min,
                                    double s_max) {
    const glm::dvec3 n = glm::cross(triangle.p2 - triangle.p1, triangle.p3 - triangle.p1);
    const double len = safe_length(n);
    if (!(len > 0.0) || !std::isfinite(len)) return std::nullopt;
    const auto bary =
        intersect_barycentric(triangle.p1, triangle.p2, triangle.p3, ray, s_min, s_max);
    if (!bary) return std::nullopt;
    SurfaceHit hit;
    hit.s = bary->s;
    hit.normal = n / len;
    hit.shading_normal = hit.normal;
    hit.uv = {bary->b2, bary->b3};
    hit.part = 0;
    place_barycentric_hit(*bary, triangle.p1, triangle.p2, triangle.p3, ray, hit);
    if (!is_finite(hit)) return std::nullopt;
    return hit;
}

void place_barycentric_hit(const BarycentricHit& hit, const glm::dvec3& p1, const glm::dvec3& p2,
                           const glm::dvec3& p3, const Ray3& ray, SurfaceHit& out) {
    out.point = hit.b1 * p1 + hit.b2 * p2 + hit.b3 * p3;
    out.error = barycentric_error(hit, p1, p2, p3);
    if (!std::isfinite(hit.s_error)) return;
    // origin + s direction in one rounding (fma) of the sum's magnitude,
    // and s's own error carried along the direction.
    const glm::dvec3 along{std::fma(hit.s, ray.direction.x, ray.origin.x),
                           std::fma(hit.s, ray.direction.y, ray.origin.y),
                           std::fma(hit.s, ray.direction.z, ray.origin.z)};
    const glm::dvec3 along_error =
        glm::abs(ray.direction) * (hit.s_error * (1.0 + rounding_gamma(2))) +
        rounding_gamma(2) * (glm::abs(ray.origin) + glm::abs(hit.s * ray.direction));
    if (is_finite(along) && is_finite(along_error) && max_abs(along_error) < max_abs(out.error)) {
        out.point = along;
        out.error = along_error;
    }
}

bool inside(const TriangleGeometry&, glm::dvec3) {
    return false;
}

Box3 object_bounds(const TriangleGeometry& triangle) {
    return {glm::min(triangle.p1, glm::min(triangle.p2, triangle.p3)),
            glm::max(triangle.p1, glm::max(triangle.p2, triangle.p3))};
}

bool triangle_may_meet(const glm::dvec3& p1, const glm::dvec3& p2, const glm::dvec3& p3,
                       const Box3& box) {
    const double slack = meet_slack(box, std::max({max_abs(p1), max_abs(p2), max_abs(p3)}));
    const glm::dvec3 c = centre(box);
    const glm::dvec3 h = 0.5 * (box.hi - box.lo) + slack;
    const glm::dvec3 v[3] = {p1 - c, p2 - c, p3 - c};
    // Separated along axis a when the triangle's projection lies beyond the
    // box's projection radius; the rounding of the projections (a few ulps of
    // |v| |a|) is covered by a further slack along the axis.
    auto separated = [&](const glm::dvec3& a) {
        const double p0 = glm::dot(v[0], a), q1 = glm::dot(v[1], a), q2 = glm::dot(v[2], a);
        const glm::dvec3 abs_a = glm::abs(a);
        const double radius = glm::dot(h, abs_a) + 2.0 * slack * (abs_a.x + abs_a.y + abs_a.z);
        return std::min({p0, q1, q2}) > radius || std::max({p0, q1, q2}) < -radius;
    };
    for (int k = 0; k < 3; ++k) {
        glm::dvec3 axis(0.0);
        axis[k] = 1.0;
        if (separated(axis)) return false;
    }
    const glm::dvec3 e[3] = {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
    if (separated(glm::cross(e[0], e[1]))) return false;
    for (int i = 0; i < 3; ++i) {
        for (int k = 0; k < 3; ++k) {
            glm::dvec3 axis(0.0);
            axis[k] = 1.0;
            if (separated(glm::cross(e[i], axis))) return false;
        }
    }
    return true;
}

bool surface_may_meet(const TriangleGeometry& triangle, const Box3& box) {
    return triangle_may_meet(triangle.p1, triangle.p2, triangle.p3, box);
}

}  // namespace hexant::runtime::geometry
