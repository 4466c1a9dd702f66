#include "runtime/objects/plane/plane_geometry.hpp"

#include <cmath>

#include "runtime/geometry/box_queries.hpp"
#include "runtime/geometry/orthonormal_basis.hpp"
#include "runtime/geometry/stable_arithmetic.hpp"

namespace hexant::runtime::geometry {

namespace {

// The unit normal, or zero for a degenerate plane.
glm::dvec3 unit_normal(const PlaneGeometry& plane) {
    const double len = safe_length(plane.normal);
    if (!(len > 0.0) || !std::isfinite(len)) return glm::dvec3(0.0);
    return plane.normal / len;
}

}  // namespace

std::optional<SurfaceHit> intersect(const PlaneGeometry& plane, const Ray3& ray, double s_min,
                                    double s_max) {
    const glm::dvec3 n = unit_normal(plane);
    if (n == glm::dvec3(0.0) || !std::isfinite(plane.distance)) return std::nullopt;
    if (!is_finite(ray.origin) || !is_finite(ray.direction)) return std::nullopt;
    // s = (distance - dot(origin, n)) / dot(direction, n). A plane has no
    // centre to move the origin to, and far from the origin the numerator
    // is a small difference of large numbers; at grazing incidence so is the
    // denominator. Both are evaluated in effectively doubled precision, on
    // the direction as given (normalising it would round it).
    const double along = -compensated_offset(0.0, ray.direction, n);
    if (along == 0.0 || !std::isfinite(along)) return std::nullopt;  // parallel: no 0/0
    const double s = compensated_offset(plane.distance, ray.origin, n) / along;
    if (!(s > s_min && s < s_max)) return std::nullopt;
    SurfaceHit hit;
    hit.s = s;
    glm::dvec3 p{std::fma(s, ray.direction.x, ray.origin.x),
                 std::fma(s, ray.direction.y, ray.origin.y),
                 std::fma(s, ray.direction.z, ray.origin.z)};
    p -= (glm::dot(p, n) - plane.distance) * n;  // one projection step onto the plane
    hit.point = p;
    hit.normal = n;
    hit.shading_normal = n;
    const OrthonormalBasis basis = orthonormal_basis(n);
    hit.uv = {glm::dot(p, basis.t1), glm::dot(p, basis.t2)};
    hit.part = 0;
    if (!is_finite(hit)) return std::nullopt;
    return hit;
}

bool inside(const PlaneGeometry& plane, glm::dvec3 p) {
    const glm::dvec3 n = unit_normal(plane);
    if (n == glm::dvec3(0.0)) return false;
    return glm::dot(p, n) <= plane.distance;
}

bool surface_may_meet(const PlaneGeometry& plane, const Box3& box) {
    const glm::dvec3 n = unit_normal(plane);
    if (n == glm::dvec3(0.0)) return false;
    const double slack = meet_slack(box, plane.distance);
    return straddles_plane(box, n, plane.distance, slack);
}

}  // namespace hexant::runtime::geometry
