// The sphere's time functions: centre and radius.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "runtime/objects/model_support.hpp"
#include "runtime/objects/sphere/sphere.hpp"
#include "runtime/objects/sphere/sphere_geometry.hpp"
#include "runtime/time/interval_matrix.hpp"

namespace hexant::runtime::objects {

class SphereModel {
  public:
    using Geometry = geometry::SphereGeometry;
    static constexpr bool kSolid = true;
    static constexpr bool kUvMapping = true;  // POV-Ray 3.7 maps it (primitive.hpp)

    explicit SphereModel(const Sphere& s) : center_(s.center), radius_(s.radius) {}

    bool is_static() const { return center_.is_constant() && radius_.is_constant(); }
    Geometry at(double t) const { return {center_.at(t), radius_.at(t)}; }
    IntervalBox box_over(const Interval& t) const {
        return ball_box(center_.over(t), radius_.over(t));
    }
    // The box of the sphere g under the affine map m: the centre's image,
    // plus r times the length of each row of m's linear part on that axis
    // (the extent of an ellipsoid). The lengths are rounded up by 8 ulps
    // (the sum of three squares and the root: 5 roundings) and the centre
    // is an interval product, so the box holds the exact image.
    static IntervalBox placed_box(const Geometry& g, const AffineMap<double>& m) {
        const IntervalBox center =
            m.apply(IntervalBox{Interval(g.center.x), Interval(g.center.y), Interval(g.center.z)});
        const double r = std::max(g.radius, 0.0);
        IntervalBox out;
        for (int i = 0; i < 3; ++i) {
            const double length =
                std::sqrt(m.m[i][0] * m.m[i][0] + m.m[i][1] * m.m[i][1] + m.m[i][2] * m.m[i][2]);
            const double h = interval_detail::up(
                r * length * (1.0 + 8.0 * std::numeric_limits<double>::epsilon()), 2);
            out[i] = center[i] + Interval(-h, h);
        }
        return out;
    }
    double surface_motion(const Interval& t, const Geometry& mid) const {
        return deviation(center_, t, mid.center) + deviation(radius_, t, mid.radius);
    }
    // Texture coordinates of a hit, from its object-space normal (the
    // routine leaves them to this: runtime/objects/sphere/sphere_geometry.hpp).
    static glm::dvec2 uv(const glm::dvec3& object_normal) {
        return geometry::sphere_uv(object_normal);
    }
    static double volume(const Geometry& g) {
        return g.radius > 0.0 ? 4.0 / 3.0 * std::numbers::pi * g.radius * g.radius * g.radius : 0.0;
    }

  private:
    CompiledVector3 center_;
    CompiledScalar radius_;
};

}  // namespace hexant::runtime::objects
