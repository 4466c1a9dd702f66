// The sphere's time functions: centre and radius.
#pragma once

#include <numbers>

#include "runtime/geometry/sphere.hpp"
#include "runtime/objects/model_support.hpp"
#include "runtime/shapes.hpp"

namespace hexant::runtime::objects {

class SphereModel {
public:
    using Geometry = geometry::SphereGeometry;
    static constexpr bool kSolid = true;

    explicit SphereModel(const Sphere& s) : center_(s.center), radius_(s.radius) {}

    bool is_static() const { return center_.is_constant() && radius_.is_constant(); }
    Geometry at(double t) const { return {center_.at(t), radius_.at(t)}; }
    IntervalBox box_over(const Interval& t) const {
        return ball_box(center_.over(t), radius_.over(t));
    }
    double surface_motion(const Interval& t, const Geometry& mid) const {
        return deviation(center_, t, mid.center) + deviation(radius_, t, mid.radius);
    }
    // Texture coordinates of a hit, from its object-space normal (the
    // routine leaves them to this: runtime/geometry/sphere.hpp).
    static glm::dvec2 uv(const glm::dvec3& object_normal) { return geometry::sphere_uv(object_normal); }
    static double volume(const Geometry& g) {
        return g.radius > 0.0 ? 4.0 / 3.0 * std::numbers::pi * g.radius * g.radius * g.radius
                              : 0.0;
    }

private:
    CompiledVector3 center_;
    CompiledScalar radius_;
};

}  // namespace hexant::runtime::objects
