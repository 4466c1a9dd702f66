// The isosurface's time functions: its function, threshold and container.
#pragma once

#include <cmath>

#include "runtime/objects/isosurface/isosurface.hpp"
#include "runtime/objects/isosurface/isosurface_geometry.hpp"
#include "runtime/objects/model_support.hpp"

namespace hexant::runtime::objects {

class IsosurfaceModel {
  public:
    using Geometry = geometry::IsosurfaceGeometry;
    static constexpr bool kSolid = true;

    explicit IsosurfaceModel(const Isosurface& s)
        : function_(s.function.value_or(TimeFunction(1.0))),
          threshold_(s.threshold),
          corner1_(s.corner1),
          corner2_(s.corner2),
          center_(s.center),
          radius_(s.radius),
          sphere_(s.sphere_container),
          open_(s.open),
          accuracy_(s.accuracy),
          max_gradient_(s.max_gradient),
          sampled_(function_.unbounded_part() != nullptr),
          moving_function_(function_.depends_on_time()) {}

    bool is_static() const {
        return !moving_function_ && threshold_.is_constant() && corner1_.is_constant() &&
               corner2_.is_constant() && center_.is_constant() && radius_.is_constant();
    }
    Geometry at(double t) const {
        Geometry g;
        g.function = function_;
        g.time = t;
        g.threshold = threshold_.at(t);
        g.sphere = sphere_;
        g.open = open_;
        g.accuracy = accuracy_;
        g.sampled = sampled_;
        g.max_gradient = max_gradient_;
        if (sphere_) {
            g.center = center_.at(t);
            g.radius = radius_.at(t);
        } else {
            const glm::dvec3 a = corner1_.at(t), b = corner2_.at(t);
            g.lo = glm::min(a, b);
            g.hi = glm::max(a, b);
        }
        return g;
    }
    // The container's box over the times.
    IntervalBox box_over(const Interval& t) const {
        if (sphere_) return ball_box(center_.over(t), radius_.over(t));
        const IntervalBox a = corner1_.over(t), b = corner2_.over(t);
        return hull(a, b);
    }
    // A surface that moves (its function, threshold or container) can be
    // anywhere in the container at another instant: the container's
    // diagonal over the times bounds how far it moves.
    double surface_motion(const Interval& t, const Geometry&) const {
        if (is_static()) return 0.0;
        const IntervalBox box = box_over(t);
        double sum = 0.0;
        for (const Interval& side : box) sum += side.width() * side.width();
        return std::nextafter(std::sqrt(sum) * (1.0 + 1e-15), INFINITY);
    }
    // No closed form: the caller samples.
    static double volume(const Geometry&) { return -1.0; }

  private:
    SpaceFunction function_;
    CompiledScalar threshold_;
    CompiledVector3 corner1_, corner2_, center_;
    CompiledScalar radius_;
    bool sphere_, open_;
    double accuracy_, max_gradient_;
    bool sampled_;
    bool moving_function_;
};

}  // namespace hexant::runtime::objects
