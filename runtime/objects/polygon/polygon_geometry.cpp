#include "runtime/objects/polygon/polygon_geometry.hpp"

#include <array>
#include <cmath>

#include "runtime/geometry/box_queries.hpp"
#include "runtime/geometry/local_ray.hpp"
#include "runtime/geometry/outline.hpp"
#include "runtime/geometry/stable_arithmetic.hpp"

namespace hexant::runtime::geometry {

namespace {

// The most points whose projections a ray keeps on the stack (larger
// polygons project each edge's ends as they come).
constexpr std::size_t kProjectedAtOnce = 32;

bool polygon_plane(const PolygonGeometry& polygon, PolygonPlane& plane) {
    const std::vector<glm::dvec3>& p = polygon.points;
    if (p.size() < 3) return false;
    const glm::dvec3 p0 = p[0];
    std::size_t first = 1;
    while (first < p.size() && p[first] == p0) ++first;
    if (first == p.size()) return false;
    const glm::dvec3 u = p[first] - p0;
    // POV-Ray's side: the first cross product clearly off zero (relative to
    // its factors, so the choice does not depend on the polygon's scale).
    glm::dvec3 side(0.0), best(0.0);
    double best_length = 0.0;
    const double u_length = safe_length(u);
    for (std::size_t j = first + 1; j < p.size(); ++j) {
        const glm::dvec3 v = p[j] - p0;
        const glm::dvec3 w = glm::cross(u, v);
        const double w_length = safe_length(w);
        if (side == glm::dvec3(0.0) && w_length > 64.0 * kEpsilon * u_length * safe_length(v)) {
            side = w;
        }
        if (w_length > best_length) {
            best_length = w_length;
            best = w;
        }
    }
    if (side == glm::dvec3(0.0) || !(best_length > 0.0) || !std::isfinite(best_length)) {
        return false;
    }
    plane.origin = p0;
    plane.normal = (glm::dot(best, side) < 0.0 ? -best : best) / best_length;
    plane.e1 = u / u_length;
    plane.e2 = glm::cross(plane.normal, plane.e1);
    const glm::dvec3 a = glm::abs(plane.normal);
    const int drop = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
    plane.kx = (drop + 1) % 3;
    plane.ky = (drop + 2) % 3;
    return true;
}

Box3 bounds_of(const std::vector<glm::dvec3>& points) {
    if (points.empty()) return {glm::dvec3(0.0), glm::dvec3(0.0)};
    Box3 b{points[0], points[0]};
    for (const glm::dvec3& q : points) {
        b.lo = glm::min(b.lo, q);
        b.hi = glm::max(b.hi, q);
    }
    return b;
}

}  // namespace

PolygonGeometry& prepare_polygon(PolygonGeometry& polygon) {
    PolygonGeometry::Prepared p;
    p.has_plane = polygon_plane(polygon, p.plane);
    p.bounds = bounds_of(polygon.points);
    std::vector<bool> ends(polygon.points.size(), false);
    for_each_outline_edge(polygon.points.data(), polygon.points.size(),
                          [&](std::size_t i, std::size_t j) {
                              p.edges.push_back({std::uint32_t(i), std::uint32_t(j)});
                              ends[i] = ends[j] = true;
                          });
    for (std::size_t k = 0; k < ends.size(); ++k)
        if (ends[k]) p.ends.push_back(std::uint32_t(k));
    polygon.prepared = std::move(p);
    return polygon;
}

std::optional<SurfaceHit> intersect(const PolygonGeometry& polygon, const Ray3& ray, double s_min,
                                    double s_max) {
    PolygonPlane plane;
    Box3 bounds;
    if (polygon.prepared) {
        if (!polygon.prepared->has_plane) return std::nullopt;
        plane = polygon.prepared->plane;
        bounds = polygon.prepared->bounds;
    } else {
        if (!polygon_plane(polygon, plane)) return std::nullopt;
        bounds = object_bounds(polygon);
    }
    const auto local = local_ray(ray, centre(bounds), half_diagonal(bounds));
    if (!local) return std::nullopt;
    const double along = glm::dot(local->unit, plane.normal);
    if (along == 0.0) return std::nullopt;  // parallel: no hit, and no 0/0
    const double t = glm::dot(plane.origin - local->origin, plane.normal) / along;
    const double s = local->to_s(t);
    if (!(s > s_min && s < s_max)) return std::nullopt;
    glm::dvec3 point = local->at(t);
    point -= glm::dot(point - plane.origin, plane.normal) * plane.normal;
    // Inside or not is decided in the ray's own sheared frame, as the
    // watertight triangle test does (Woop et al.): vertices relative to the
    // ray's origin, sheared so the ray runs along an axis, and the ray's foot
    // at the 2D origin. Each vertex's 2D position depends only on it and the
    // ray, so polygons sharing an edge decide the edge alike: no ray slips
    // between them.
    const glm::dvec3& d = ray.direction;
    int kz = 0;
    if (std::fabs(d.y) > std::fabs(d[kz])) kz = 1;
    if (std::fabs(d.z) > std::fabs(d[kz])) kz = 2;
    const int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    const double sx = d[kx] / d[kz], sy = d[ky] / d[kz];
    const glm::dvec3 o = ray.origin;
    auto sheared = [&](const glm::dvec3& q) {
        const glm::dvec3 a = q - o;
        return glm::dvec2(a[kx] - sx * a[kz], a[ky] - sy * a[kz]);
    };
    if (polygon.prepared && polygon.points.size() <= kProjectedAtOnce) {
        std::array<glm::dvec2, kProjectedAtOnce> relative;
        for (const std::uint32_t k : polygon.prepared->ends)
            relative[k] = sheared(polygon.points[k]);
        if (!inside_even_odd_relative(relative.data(), polygon.prepared->edges.data(),
                                      polygon.prepared->edges.size()))
            return std::nullopt;
    } else if (!inside_even_odd(polygon.points.data(), polygon.points.size(), sheared,
                                glm::dvec2(0.0))) {
        return std::nullopt;
    }
    SurfaceHit hit;
    hit.s = s;
    hit.point = point;
    hit.normal = plane.normal;
    hit.shading_normal = plane.normal;
    const glm::dvec3 from_origin = point - plane.origin;
    hit.uv = {glm::dot(from_origin, plane.e1), glm::dot(from_origin, plane.e2)};
    hit.part = 0;
    if (!is_finite(hit)) return std::nullopt;
    return hit;
}

bool inside(const PolygonGeometry&, glm::dvec3) {
    return false;
}

Box3 object_bounds(const PolygonGeometry& polygon) {
    return polygon.prepared ? polygon.prepared->bounds : bounds_of(polygon.points);
}

bool surface_may_meet(const PolygonGeometry& polygon, const Box3& box) {
    PolygonPlane plane;
    if (polygon.prepared) {
        if (!polygon.prepared->has_plane) return false;
        plane = polygon.prepared->plane;
    } else if (!polygon_plane(polygon, plane)) {
        return false;
    }
    const Box3 bounds = object_bounds(polygon);
    const double slack = meet_slack(box, std::max(max_abs(bounds.lo), max_abs(bounds.hi)));
    const Box3 wide = widened(box, slack);
    if (!overlaps(wide, widened(bounds, slack))) return false;
    if (!straddles_plane(box, plane.normal, glm::dot(plane.origin, plane.normal), slack)) {
        return false;
    }
    // Dropping the normal's largest axis maps the plane one-to-one onto the
    // other two axes, and the plane's part inside the box into the box's
    // rectangle there: the region meeting that rectangle is necessary.
    const int kx = plane.kx, ky = plane.ky;
    auto project = [kx, ky](const glm::dvec3& q) { return glm::dvec2(q[kx], q[ky]); };
    return region_meets_rectangle(polygon.points.data(), polygon.points.size(), project,
                                  project(wide.lo), project(wide.hi));
}

}  // namespace hexant::runtime::geometry
