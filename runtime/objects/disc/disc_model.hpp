// The disc's time functions: centre, normal, radius and hole radius.
#pragma once

#include "runtime/objects/disc/disc.hpp"
#include "runtime/objects/disc/disc_geometry.hpp"
#include "runtime/objects/model_support.hpp"

namespace hexant::runtime::objects {

// How far a unit direction, normalize(v(t)), strays from normalize(at_mid)
// over t: the surface of a disc, cylinder or cone turns with it, moving a
// point at distance rho from the axis by at most rho times this.
inline double direction_deviation(const CompiledVector3& v, const Interval& t,
                                  const glm::dvec3& at_mid) {
    if (v.is_constant()) return 0.0;
    const IntervalBox range = v.over(t);
    const Interval length = sqrt(sqr(range[0]) + sqr(range[1]) + sqr(range[2]));
    const double mid_length = glm::length(at_mid);
    if (!(length.lo > 0.0) || !(mid_length > 0.0)) return 2.0;  // any turn: |a - b| <= 2
    double sum = 0.0;
    for (int i = 0; i < 3; ++i) {
        const double d = (range[i] / length - Interval(at_mid[i] / mid_length)).magnitude();
        sum += d * d;
    }
    return std::min(2.0, std::sqrt(sum) * (1.0 + 1e-15));
}

class DiscModel {
  public:
    using Geometry = geometry::DiscGeometry;
    static constexpr bool kSolid = false;
    static constexpr bool kFlat = true;

    explicit DiscModel(const Disc& d)
        : center_(d.center), normal_(d.normal), radius_(d.radius), hole_(d.hole_radius) {}

    bool is_static() const {
        return center_.is_constant() && normal_.is_constant() && radius_.is_constant() &&
               hole_.is_constant();
    }
    Geometry at(double t) const {
        return {center_.at(t), normal_.at(t), radius_.at(t), hole_.at(t)};
    }
    IntervalBox box_over(const Interval& t) const {
        return ball_box(center_.over(t), radius_.over(t));
    }
    double surface_motion(const Interval& t, const Geometry& mid) const {
        const double r = std::max(radius_.over(t).hi, 0.0);
        return deviation(center_, t, mid.center) + r * direction_deviation(normal_, t, mid.normal) +
               std::max(deviation(radius_, t, mid.radius), deviation(hole_, t, mid.hole_radius));
    }
    static double volume(const Geometry&) { return 0.0; }

  private:
    CompiledVector3 center_, normal_;
    CompiledScalar radius_, hole_;
};

}  // namespace hexant::runtime::objects
