#include "runtime/objects/triangle/triangle_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "runtime/geometry/box_queries.hpp"
#include "runtime/geometry/stable_arithmetic.hpp"

namespace hexant::runtime::geometry {

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
    if (s_min >= 0.0) {
        using std::fabs;
        const double max_z = std::max({fabs(az), fabs(bz), fabs(cz)});
        const double spread_z = std::max({az, bz, cz}) - std::min({az, bz, cz});
        const double max_x = std::max({fabs(ax), fabs(bx), fabs(cx)});
        const double max_y = std::max({fabs(ay), fabs(by), fabs(cy)});
        const double delta_x = rounding_gamma(5) * (max_x + max_z);
        const double delta_y = rounding_gamma(5) * (max_y + max_z);
        const double delta_e =
            2.0 * (rounding_gamma(2) * max_x * max_y + delta_y * max_x + delta_x * max_y);
        const double sum_e = fabs(eu) + fabs(ev) + fabs(ew);
        const double delta_t =
            2.0 * (2.0 * rounding_gamma(3) * max_z * sum_e + 3.0 * delta_e * spread_z) / fabs(det);
        if (!(t > delta_t)) return std::nullopt;
    }
    const double s = std::ldexp(t, -exponent);
    if (!(s > s_min && s < s_max)) return std::nullopt;
    const double inv = 1.0 / det;
    return BarycentricHit{s, eu * inv, ev * inv, ew * inv};
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
    hit.point = bary->b1 * triangle.p1 + bary->b2 * triangle.p2 + bary->b3 * triangle.p3;
    hit.error = barycentric_error(*bary, triangle.p1, triangle.p2, triangle.p3);
    if (!is_finite(hit)) return std::nullopt;
    return hit;
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
