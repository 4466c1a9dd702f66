// The polygon's time functions: its points (any number, several outlines).
#pragma once

#include <vector>

#include "runtime/objects/model_support.hpp"
#include "runtime/objects/polygon/polygon.hpp"
#include "runtime/objects/polygon/polygon_geometry.hpp"

namespace hexant::runtime::objects {

class PolygonModel {
  public:
    using Geometry = geometry::PolygonGeometry;
    static constexpr bool kSolid = false;
    static constexpr bool kFlat = true;

    explicit PolygonModel(const Polygon& p) {
        points_.reserve(p.points.size());
        for (const auto& point : p.points) {
            points_.emplace_back(point);
            is_static_ = is_static_ && points_.back().is_constant();
        }
    }

    bool is_static() const { return is_static_; }
    Geometry at(double t) const {
        Geometry g;
        g.points.reserve(points_.size());
        for (const auto& p : points_) g.points.push_back(p.at(t));
        return geometry::prepare_polygon(g);
    }
    IntervalBox box_over(const Interval& t) const {
        IntervalBox box = empty_interval_box();
        for (const auto& p : points_) box = hull(box, p.over(t));
        return box;
    }
    // Every point of the filled outlines is a convex blend of the vertices.
    double surface_motion(const Interval& t, const Geometry& mid) const {
        double m = 0.0;
        for (std::size_t i = 0; i < points_.size(); ++i)
            m = std::max(m, deviation(points_[i], t, mid.points[i]));
        return m;
    }
    static double volume(const Geometry&) { return 0.0; }

  private:
    std::vector<CompiledVector3> points_;
    bool is_static_ = true;
};

}  // namespace hexant::runtime::objects
