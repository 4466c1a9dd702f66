// The cylinder's and cone's time functions: end points and radii.
#pragma once

#include <numbers>

#include "runtime/objects/cylinder/cone.hpp"
#include "runtime/objects/cylinder/cone_geometry.hpp"
#include "runtime/objects/cylinder/cylinder.hpp"
#include "runtime/objects/cylinder/cylinder_geometry.hpp"
#include "runtime/objects/disc/disc_model.hpp"
#include "runtime/objects/model_support.hpp"

namespace hexant::runtime::objects {

// The axis's direction as a time function, for direction_deviation.
inline Vector3Function axis_function(const Vector3Function& base, const Vector3Function& cap) {
    Vector3Function axis;
    for (int i = 0; i < 3; ++i) axis.c[i] = cap.c[i] - base.c[i];
    return axis;
}

class CylinderModel {
  public:
    using Geometry = geometry::CylinderGeometry;
    static constexpr bool kSolid = true;

    explicit CylinderModel(const Cylinder& c)
        : base_(c.base),
          cap_(c.cap),
          axis_(axis_function(c.base, c.cap)),
          radius_(c.radius),
          open_(c.open) {}

    bool is_static() const {
        return base_.is_constant() && cap_.is_constant() && radius_.is_constant();
    }
    Geometry at(double t) const { return {base_.at(t), cap_.at(t), radius_.at(t), open_}; }
    // Inside the end balls' hull: every point is within radius of the axis segment.
    IntervalBox box_over(const Interval& t) const {
        const Interval r = radius_.over(t);
        return hull(ball_box(base_.over(t), r), ball_box(cap_.over(t), r));
    }
    double surface_motion(const Interval& t, const Geometry& mid) const {
        const double r = std::max(radius_.over(t).hi, 0.0);
        return std::max(deviation(base_, t, mid.base), deviation(cap_, t, mid.cap)) +
               r * direction_deviation(axis_, t, mid.cap - mid.base) +
               deviation(radius_, t, mid.radius);
    }
    static double volume(const Geometry& g) {
        return g.radius > 0.0 ? std::numbers::pi * g.radius * g.radius * glm::length(g.cap - g.base)
                              : 0.0;
    }

  private:
    CompiledVector3 base_, cap_, axis_;
    CompiledScalar radius_;
    bool open_;
};

class ConeModel {
  public:
    using Geometry = geometry::ConeGeometry;
    static constexpr bool kSolid = true;

    explicit ConeModel(const Cone& c)
        : base_(c.base),
          cap_(c.cap),
          axis_(axis_function(c.base, c.cap)),
          base_radius_(c.base_radius),
          cap_radius_(c.cap_radius),
          open_(c.open) {}

    bool is_static() const {
        return base_.is_constant() && cap_.is_constant() && base_radius_.is_constant() &&
               cap_radius_.is_constant();
    }
    Geometry at(double t) const {
        return {base_.at(t), base_radius_.at(t), cap_.at(t), cap_radius_.at(t), open_};
    }
    IntervalBox box_over(const Interval& t) const {
        return hull(ball_box(base_.over(t), abs(base_radius_.over(t))),
                    ball_box(cap_.over(t), abs(cap_radius_.over(t))));
    }
    double surface_motion(const Interval& t, const Geometry& mid) const {
        const double r = std::max(abs(base_radius_.over(t)).hi, abs(cap_radius_.over(t)).hi);
        return std::max(deviation(base_, t, mid.base), deviation(cap_, t, mid.cap)) +
               r * direction_deviation(axis_, t, mid.cap - mid.base) +
               std::max(deviation(base_radius_, t, mid.base_radius),
                        deviation(cap_radius_, t, mid.cap_radius));
    }
    static double volume(const Geometry& g) {
        const double a = g.base_radius, b = g.cap_radius;
        if (a < 0.0 || b < 0.0) return 0.0;
        return std::numbers::pi * glm::length(g.cap - g.base) * (a * a + a * b + b * b) / 3.0;
    }

  private:
    CompiledVector3 base_, cap_, axis_;
    CompiledScalar base_radius_, cap_radius_;
    bool open_;
};

}  // namespace hexant::runtime::objects
