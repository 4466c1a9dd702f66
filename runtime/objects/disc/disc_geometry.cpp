#include "runtime/objects/disc/disc_geometry.hpp"

#include <cmath>

#include "runtime/geometry/box_queries.hpp"
#include "runtime/geometry/orthonormal_basis.hpp"
#include "runtime/geometry/stable_arithmetic.hpp"

namespace hexant::runtime::geometry {

namespace {

bool unit_normal(const DiscGeometry& disc, glm::dvec3& n) {
    const double len = safe_length(disc.normal);
    if (!(len > 0.0) || !std::isfinite(len)) return false;
    n = disc.normal / len;
    return true;
}

}  // namespace

std::optional<DiscCrossing> cross_disc(const LocalRay& ray, const glm::dvec3& center,
                                       const glm::dvec3& unit_normal, double radius,
                                       double hole_radius) {
    const double along = glm::dot(ray.unit, unit_normal);
    if (along == 0.0) return std::nullopt;  // parallel: no hit, and no 0/0
    const glm::dvec3 f = ray.origin - center;
    const double t = -glm::dot(f, unit_normal) / along;
    if (!std::isfinite(t)) return std::nullopt;
    glm::dvec3 radial = f + t * ray.unit;
    radial -= glm::dot(radial, unit_normal) * unit_normal;  // remove the rounding off the plane
    const double r = safe_length(radial);
    if (!(r <= radius) || r < hole_radius) return std::nullopt;
    return DiscCrossing{t, radial};
}

bool disc_may_meet(const glm::dvec3& center, const glm::dvec3& unit_normal, double radius,
                   double hole_radius, const Box3& box) {
    if (!(radius > 0.0)) return false;
    const double slack = meet_slack(box, max_abs(center) + radius);
    if (!straddles_plane(box, unit_normal, glm::dot(center, unit_normal), slack)) return false;
    // Every disc point lies within radius of the centre and beyond the hole.
    const Box3 wide = widened(box, slack);
    return !(min_distance(wide, center) > radius + slack) &&
           !(max_distance(wide, center) < hole_radius - slack);
}

std::optional<SurfaceHit> intersect(const DiscGeometry& disc, const Ray3& ray, double s_min,
                                    double s_max) {
    glm::dvec3 n;
    if (!unit_normal(disc, n) || !(disc.radius > 0.0) || !std::isfinite(disc.radius)) {
        return std::nullopt;
    }
    const auto local = local_ray(ray, disc.center, disc.radius);
    if (!local) return std::nullopt;
    const auto crossing = cross_disc(*local, disc.center, n, disc.radius, disc.hole_radius);
    if (!crossing) return std::nullopt;
    SurfaceHit hit;
    hit.s = local->to_s(crossing->t);
    if (!(hit.s > s_min && hit.s < s_max)) return std::nullopt;
    hit.point = disc.center + crossing->radial;
    hit.normal = n;
    hit.shading_normal = n;
    hit.uv = {turn_fraction(orthonormal_basis(n), crossing->radial),
              safe_length(crossing->radial) / disc.radius};
    hit.part = 0;
    if (!is_finite(hit)) return std::nullopt;
    return hit;
}

bool inside(const DiscGeometry&, glm::dvec3) {
    return false;
}

Box3 object_bounds(const DiscGeometry& disc) {
    glm::dvec3 n;
    if (!unit_normal(disc, n)) return {disc.center, disc.center};
    return disc_bounds(disc.center, n, disc.radius);
}

bool surface_may_meet(const DiscGeometry& disc, const Box3& box) {
    glm::dvec3 n;
    if (!unit_normal(disc, n)) return false;
    return disc_may_meet(disc.center, n, disc.radius, disc.hole_radius, box);
}

}  // namespace hexant::runtime::geometry
