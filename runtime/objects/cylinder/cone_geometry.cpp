#include "runtime/objects/cylinder/cone_geometry.hpp"

#include "runtime/objects/cylinder/frustum.hpp"

namespace hexant::runtime::geometry {

namespace {

Frustum as_frustum(const ConeGeometry& c) {
    return {c.base, c.cap, c.base_radius, c.cap_radius, c.open};
}

}  // namespace

std::optional<SurfaceHit> intersect(const ConeGeometry& cone, const Ray3& ray, double s_min,
                                    double s_max) {
    return intersect_frustum(as_frustum(cone), ray, s_min, s_max);
}

bool inside(const ConeGeometry& cone, glm::dvec3 p) {
    return inside_frustum(as_frustum(cone), p);
}

Box3 object_bounds(const ConeGeometry& cone) {
    return frustum_bounds(as_frustum(cone));
}

bool surface_may_meet(const ConeGeometry& cone, const Box3& box) {
    return frustum_may_meet(as_frustum(cone), box);
}

}  // namespace hexant::runtime::geometry
