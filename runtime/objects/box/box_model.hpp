// The box's time functions: its two corners.
#pragma once

#include <cmath>

#include "runtime/objects/box/box.hpp"
#include "runtime/objects/box/box_geometry.hpp"
#include "runtime/objects/model_support.hpp"

namespace hexant::runtime::objects {

class BoxModel {
  public:
    using Geometry = geometry::BoxGeometry;
    static constexpr bool kSolid = true;
    static constexpr bool kConvex = true;
    static constexpr bool kUvMapping = true;  // POV-Ray 3.7 maps it (primitive.hpp)

    explicit BoxModel(const Box& b) : corner1_(b.corner1), corner2_(b.corner2) {}

    bool is_static() const { return corner1_.is_constant() && corner2_.is_constant(); }
    Geometry at(double t) const { return {corner1_.at(t), corner2_.at(t)}; }
    IntervalBox box_over(const Interval& t) const {
        return hull(corner1_.over(t), corner2_.over(t));
    }
    // Every surface point is a blend of the corners' coordinates.
    double surface_motion(const Interval& t, const Geometry& mid) const {
        return std::max(deviation(corner1_, t, mid.corner1), deviation(corner2_, t, mid.corner2));
    }
    static double volume(const Geometry& g) {
        const glm::dvec3 e = glm::abs(g.corner2 - g.corner1);
        return e.x * e.y * e.z;
    }

  private:
    CompiledVector3 corner1_, corner2_;
};

}  // namespace hexant::runtime::objects
