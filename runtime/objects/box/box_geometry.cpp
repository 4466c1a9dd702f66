#include "runtime/objects/box/box_geometry.hpp"

#include <cmath>
#include <limits>

#include "runtime/geometry/box_queries.hpp"
#include "runtime/geometry/local_ray.hpp"

namespace hexant::runtime::geometry {

namespace {

// POV-Ray's cube map: the faces unfolded into a cross in a 4 x 3 grid, each
// seen from outside without mirroring.
glm::dvec2 box_uv(const Box3& b, const glm::dvec3& point, int part) {
    const glm::dvec3 size = b.hi - b.lo;
    glm::dvec3 p(0.0);
    for (int k = 0; k < 3; ++k) p[k] = size[k] > 0.0 ? (point[k] - b.lo[k]) / size[k] : 0.0;
    switch (part) {
        case 0:
            return {p.z / 4.0, 1.0 / 3.0 + p.y / 3.0};
        case 1:
            return {3.0 / 4.0 - p.z / 4.0, 1.0 / 3.0 + p.y / 3.0};
        case 2:
            return {1.0 / 4.0 + p.x / 4.0, p.z / 3.0};
        case 3:
            return {1.0 / 4.0 + p.x / 4.0, 1.0 - p.z / 3.0};
        case 4:
            return {1.0 - p.x / 4.0, 1.0 / 3.0 + p.y / 3.0};
        default:
            return {1.0 / 4.0 + p.x / 4.0, 1.0 / 3.0 + p.y / 3.0};
    }
}

}  // namespace

std::optional<SurfaceHit> intersect(const BoxGeometry& box, const Ray3& ray, double s_min,
                                    double s_max) {
    const Box3 b = object_bounds(box);
    if (!is_finite(b.lo) || !is_finite(b.hi)) return std::nullopt;
    const auto local = local_ray(ray, centre(b), half_diagonal(b));
    if (!local) return std::nullopt;
    const glm::dvec3& o = local->origin;
    const glm::dvec3& u = local->unit;
    constexpr double kInf = std::numeric_limits<double>::infinity();
    double t_enter = -kInf, t_exit = kInf;
    int enter_part = -1, exit_part = -1;
    for (int k = 0; k < 3; ++k) {
        if (u[k] == 0.0) {
            // Parallel to this slab: inside it for all t, or never. Dividing
            // would give 0 * inf = NaN for an origin on a face plane.
            if (o[k] < b.lo[k] || o[k] > b.hi[k]) return std::nullopt;
            continue;
        }
        // Division, not multiplication by 1/u: a subnormal u would make the
        // reciprocal infinite and 0 * inf NaN; a quotient of a finite by a
        // non-zero number is never NaN.
        const double t_lo = (b.lo[k] - o[k]) / u[k];
        const double t_hi = (b.hi[k] - o[k]) / u[k];
        const bool forward = u[k] > 0.0;
        const double near = forward ? t_lo : t_hi, far = forward ? t_hi : t_lo;
        if (near > t_enter) {
            t_enter = near;
            enter_part = 2 * k + (forward ? 0 : 1);
        }
        if (far < t_exit) {
            t_exit = far;
            exit_part = 2 * k + (forward ? 1 : 0);
        }
    }
    if (!(t_enter <= t_exit)) return std::nullopt;
    const double ts[2] = {t_enter, t_exit};
    const int parts[2] = {enter_part, exit_part};
    for (int i = 0; i < 2; ++i) {
        if (parts[i] < 0) continue;
        const double s = local->to_s(ts[i]);
        if (!(s > s_min && s < s_max)) continue;
        const int axis = parts[i] / 2;
        const bool upper = parts[i] % 2 == 1;
        SurfaceHit hit;
        hit.s = s;
        hit.point = glm::clamp(local->at(ts[i]), b.lo, b.hi);
        hit.point[axis] = upper ? b.hi[axis] : b.lo[axis];  // exactly on the face
        hit.normal = glm::dvec3(0.0);
        hit.normal[axis] = upper ? 1.0 : -1.0;
        hit.shading_normal = hit.normal;
        hit.part = parts[i];
        hit.uv = box_uv(b, hit.point, hit.part);
        if (is_finite(hit)) return hit;
    }
    return std::nullopt;
}

bool inside(const BoxGeometry& box, glm::dvec3 p) {
    return contains(object_bounds(box), p);
}

Box3 object_bounds(const BoxGeometry& box) {
    return {glm::min(box.corner1, box.corner2), glm::max(box.corner1, box.corner2)};
}

bool surface_may_meet(const BoxGeometry& box, const Box3& region) {
    const Box3 b = object_bounds(box);
    const double slack = meet_slack(region, std::max(max_abs(b.lo), max_abs(b.hi)));
    const Box3 r = widened(region, slack);
    if (!overlaps(r, b)) return false;
    // The boundary is missed only by a region strictly inside the interior.
    const bool strictly_inside = b.lo.x < r.lo.x && r.hi.x < b.hi.x && b.lo.y < r.lo.y &&
                                 r.hi.y < b.hi.y && b.lo.z < r.lo.z && r.hi.z < b.hi.z;
    return !strictly_inside;
}

}  // namespace hexant::runtime::geometry
