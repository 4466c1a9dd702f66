#include "runtime/objects/cylinder/cylinder_geometry.hpp"

#include "runtime/objects/cylinder/frustum.hpp"

namespace hexant::runtime::geometry {

namespace {

Frustum as_frustum(const CylinderGeometry& c) {
    return {c.base, c.cap, c.radius, c.radius, c.open};
}

}  // namespace

std::optional<SurfaceHit> intersect(const CylinderGeometry& cylinder, const Ray3& ray, double s_min,
                                    double s_max) {
    return intersect_frustum(as_frustum(cylinder), ray, s_min, s_max);
}

bool inside(const CylinderGeometry& cylinder, glm::dvec3 p) {
    return inside_frustum(as_frustum(cylinder), p);
}

Box3 object_bounds(const CylinderGeometry& cylinder) {
    return frustum_bounds(as_frustum(cylinder));
}

bool surface_may_meet(const CylinderGeometry& cylinder, const Box3& box) {
    return frustum_may_meet(as_frustum(cylinder), box);
}

}  // namespace hexant::runtime::geometry
