#include "runtime/objects/sphere/sphere_geometry.hpp"

#include <algorithm>
#include <cmath>

#include "runtime/geometry/box_queries.hpp"
#include "runtime/geometry/local_ray.hpp"
#include "runtime/geometry/stable_arithmetic.hpp"

namespace hexant::runtime::geometry {

namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

glm::dvec2 sphere_uv(const glm::dvec3& n) {
    double u = std::atan2(n.z, n.x) / (2.0 * kPi);
    if (u < 0.0) u += 1.0;
    if (!(u < 1.0)) u = 0.0;
    const double v = 0.5 + std::asin(std::clamp(n.y, -1.0, 1.0)) / kPi;
    return {u, v};
}

std::optional<SurfaceHit> intersect(const SphereGeometry& sphere, const Ray3& ray, double s_min,
                                    double s_max) {
    const double r = sphere.radius;
    if (!(r > 0.0) || !std::isfinite(r) || !is_finite(sphere.center)) return std::nullopt;
    const auto local = local_ray(ray, sphere.center, r);
    if (!local) return std::nullopt;
    // |f + t u|^2 = r^2 with f = origin - center, |u| = 1:
    // t^2 + 2 (f.u) t + (|f|^2 - r^2) = 0. Ray Tracing Gems ch. 7: the
    // discriminant (f.u)^2 - (|f|^2 - r^2) equals r^2 - |f x u|^2, the squared
    // half chord, which has no cancellation until the ray grazes; both
    // differences of squares are formed as (x - y)(x + y).
    const glm::dvec3 f = local->origin - sphere.center;
    const glm::dvec3& u = local->unit;
    const double b = glm::dot(f, u);
    const double c = difference_of_squares(safe_length(f), r);
    const double disc = difference_of_squares(r, safe_length(glm::cross(f, u)));
    const QuadraticRoots roots = solve_quadratic(1.0, b, c, disc);
    for (int i = 0; i < roots.count; ++i) {
        const double t = roots.t[i];
        const double s = local->to_s(t);
        if (!(s > s_min && s < s_max)) continue;
        SurfaceHit hit;
        hit.s = s;
        const glm::dvec3 radial = f + t * u;  // point - center, formed near the sphere
        const double len = safe_length(radial);
        hit.normal = len > 0.0 ? radial / len : glm::dvec3(0.0, 1.0, 0.0);
        hit.shading_normal = hit.normal;
        hit.uv = glm::dvec2(0.0);  // sphere_uv(normal), when the hit is shaded
        hit.part = 0;
        // The point put back on the sphere along its normal (pbrt-v4's
        // refinement): centre + r n, whatever error the root carried. Each
        // coordinate is then off the exact surface by the rounding of n
        // (its length within gamma(4) of one: a norm and a division) times
        // r, and of the product and the sum (two more): within gamma(6)
        // (|c| + r), taken as gamma(8) for the margin. This is what a ray
        // leaving the sphere must clear (offset_ray): on a sphere of radius
        // 1e5 resting on y = 0 the top's error is about 1e-11, far more
        // than ulps of the point's own y near 0.
        if (len > 0.0) {
            hit.point = sphere.center + r * hit.normal;
            hit.error = rounding_gamma(8) * (glm::abs(sphere.center) + r);
        } else {
            hit.point = local->at(t);
        }
        if (is_finite(hit)) return hit;
    }
    return std::nullopt;
}

bool inside(const SphereGeometry& sphere, glm::dvec3 p) {
    return safe_length(p - sphere.center) <= sphere.radius;
}

Box3 object_bounds(const SphereGeometry& sphere) {
    const double r = std::fabs(sphere.radius);
    return {sphere.center - r, sphere.center + r};
}

bool surface_may_meet(const SphereGeometry& sphere, const Box3& box) {
    const double r = sphere.radius;
    if (!(r > 0.0)) return false;
    const double slack = meet_slack(box, max_abs(sphere.center) + r);
    const Box3 wide = widened(box, slack);
    // The sphere meets the box exactly when its radius lies between the
    // nearest and the farthest distance from the centre to the box.
    const double nearest = min_distance(wide, sphere.center);
    const double farthest = max_distance(wide, sphere.center);
    return !(nearest > r + slack) && !(farthest < r - slack);
}

}  // namespace hexant::runtime::geometry
