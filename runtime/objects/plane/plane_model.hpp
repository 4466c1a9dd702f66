// The plane's time functions: normal and distance. Unbounded: the tracer
// keeps planes outside the hierarchy.
#pragma once

#include "runtime/objects/model_support.hpp"
#include "runtime/objects/plane/plane.hpp"
#include "runtime/objects/plane/plane_geometry.hpp"

namespace hexant::runtime::objects {

class PlaneModel {
  public:
    using Geometry = geometry::PlaneGeometry;
    static constexpr bool kSolid = true;
    static constexpr bool kFlat = true;
    static constexpr bool kUnbounded = true;

    explicit PlaneModel(const Plane& p) : normal_(p.normal), distance_(p.distance) {}

    bool is_static() const { return normal_.is_constant() && distance_.is_constant(); }
    Geometry at(double t) const { return {normal_.at(t), distance_.at(t)}; }
    IntervalBox box_over(const Interval&) const {
        const Interval all = Interval::entire();
        return {all, all, all};
    }
    double surface_motion(const Interval&, const Geometry&) const {
        return std::numeric_limits<double>::infinity();
    }
    static double volume(const Geometry&) { return std::numeric_limits<double>::infinity(); }

  private:
    CompiledVector3 normal_;
    CompiledScalar distance_;
};

}  // namespace hexant::runtime::objects
