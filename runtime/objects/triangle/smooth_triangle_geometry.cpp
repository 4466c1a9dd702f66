#include "runtime/objects/triangle/smooth_triangle_geometry.hpp"

#include <cmath>

#include "runtime/geometry/stable_arithmetic.hpp"
#include "runtime/objects/triangle/triangle_geometry.hpp"

namespace hexant::runtime::geometry {

namespace {

bool unit_or_zero(const glm::dvec3& v, glm::dvec3& out) {
    const double len = safe_length(v);
    if (!(len > 0.0) || !std::isfinite(len)) return false;
    out = v / len;
    return true;
}

}  // namespace

std::optional<SurfaceHit> intersect(const SmoothTriangleGeometry& triangle, const Ray3& ray,
                                    double s_min, double s_max) {
    glm::dvec3 normal;
    if (!unit_or_zero(glm::cross(triangle.p2 - triangle.p1, triangle.p3 - triangle.p1), normal)) {
        return std::nullopt;
    }
    const auto bary =
        intersect_barycentric(triangle.p1, triangle.p2, triangle.p3, ray, s_min, s_max);
    if (!bary) return std::nullopt;
    SurfaceHit hit;
    hit.s = bary->s;
    hit.normal = normal;
    glm::dvec3 m1, m2, m3, blend;
    if (unit_or_zero(triangle.n1, m1) && unit_or_zero(triangle.n2, m2) &&
        unit_or_zero(triangle.n3, m3) &&
        unit_or_zero(bary->b1 * m1 + bary->b2 * m2 + bary->b3 * m3, blend)) {
        hit.shading_normal = blend;
    } else {
        hit.shading_normal = normal;
    }
    hit.uv = {bary->b2, bary->b3};
    hit.part = 0;
    place_barycentric_hit(*bary, triangle.p1, triangle.p2, triangle.p3, ray, hit);
    if (!is_finite(hit)) return std::nullopt;
    return hit;
}

bool inside(const SmoothTriangleGeometry&, glm::dvec3) {
    return false;
}

Box3 object_bounds(const SmoothTriangleGeometry& triangle) {
    return {glm::min(triangle.p1, glm::min(triangle.p2, triangle.p3)),
            glm::max(triangle.p1, glm::max(triangle.p2, triangle.p3))};
}

bool surface_may_meet(const SmoothTriangleGeometry& triangle, const Box3& box) {
    return triangle_may_meet(triangle.p1, triangle.p2, triangle.p3, box);
}

}  // namespace hexant::runtime::geometry
