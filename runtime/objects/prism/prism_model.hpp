// The prism's time functions: the two heights and the outline's points.
#pragma once

#include <vector>

#include "runtime/objects/model_support.hpp"
#include "runtime/objects/prism/prism.hpp"
#include "runtime/objects/prism/prism_geometry.hpp"

namespace hexant::runtime::objects {

class PrismModel {
  public:
    using Geometry = geometry::PrismGeometry;
    static constexpr bool kSolid = true;

    explicit PrismModel(const Prism& p) : height1_(p.height1), height2_(p.height2), open_(p.open) {
        is_static_ = height1_.is_constant() && height2_.is_constant();
        points_.reserve(p.points.size());
        for (const auto& point : p.points) {
            // <x, z> as a vector with y = 0, so one compiled form serves.
            points_.emplace_back(Vector3Function{{point.c[0], TimeFunction(0.0), point.c[1]}});
            is_static_ = is_static_ && points_.back().is_constant();
        }
    }

    bool is_static() const { return is_static_; }
    Geometry at(double t) const {
        Geometry g;
        g.height1 = height1_.at(t);
        g.height2 = height2_.at(t);
        g.open = open_;
        g.points.reserve(points_.size());
        for (const auto& p : points_) {
            const glm::dvec3 v = p.at(t);
            g.points.emplace_back(v.x, v.z);
        }
        return g;
    }
    IntervalBox box_over(const Interval& t) const {
        IntervalBox box = empty_interval_box();
        for (const auto& p : points_) box = hull(box, p.over(t));
        box[1] = hull(height1_.over(t), height2_.over(t));
        return box;
    }
    // Side points blend two outline points and a height; cap points blend
    // outline points at one height.
    double surface_motion(const Interval& t, const Geometry& mid) const {
        double m = 0.0;
        for (std::size_t i = 0; i < points_.size(); ++i)
            m = std::max(
                m, deviation(points_[i], t, glm::dvec3(mid.points[i].x, 0.0, mid.points[i].y)));
        return m +
               std::max(deviation(height1_, t, mid.height1), deviation(height2_, t, mid.height2));
    }
    // Nested outlines under the even-odd rule: sampled by the caller.
    static double volume(const Geometry&) { return -1.0; }

  private:
    CompiledScalar height1_, height2_;
    std::vector<CompiledVector3> points_;
    bool open_;
    bool is_static_ = true;
};

}  // namespace hexant::runtime::objects
