// The prism's time functions: the two heights and the outline's points.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "runtime/objects/model_support.hpp"
#include "runtime/objects/prism/prism.hpp"
#include "runtime/objects/prism/prism_geometry.hpp"

namespace hexant::runtime::objects {

class PrismModel {
  public:
    using Geometry = geometry::PrismGeometry;
    static constexpr bool kSolid = true;

    explicit PrismModel(const Prism& p)
        : height1_(p.height1),
          height2_(p.height2),
          open_(p.open),
          spline_(p.spline),
          sweep_(p.sweep) {
        is_static_ = height1_.is_constant() && height2_.is_constant();
        points_.reserve(p.points.size());
        for (const auto& point : p.points) {
            // <x, z> as a vector with y = 0, so one compiled form serves.
            points_.emplace_back(Vector3Function{{point.c[0], TimeFunction(0.0), point.c[1]}});
            is_static_ = is_static_ && points_.back().is_constant();
        }
    }

    bool is_static() const { return is_static_; }
    // The outline's segments are made at each instant, as POV-Ray makes them
    // for each frame (where an outline closes may depend on clock).
    Geometry at(double t) const {
        std::vector<glm::dvec2> points;
        points.reserve(points_.size());
        for (const auto& p : points_) {
            const glm::dvec3 v = p.at(t);
            points.emplace_back(v.x, v.z);
        }
        return geometry::make_prism(spline_, sweep_, height1_.at(t), height2_.at(t),
                                    std::move(points), open_);
    }
    // The outline's box: the points' hull for linear splines (a closing edge
    // joins two of them); otherwise the control hull (lathe_control_hull) of
    // every run of points a segment could be made of, whichever outlines
    // close at an instant. The heights' hull holds every height between them;
    // a conic sweep scales the outline by it (y <x, z>: interval products).
    IntervalBox box_over(const Interval& t) const {
        const IntervalBox outline = outline_over(t);
        const Interval heights = hull(height1_.over(t), height2_.over(t));
        if (sweep_ == geometry::PrismSweep::linear) return {outline[0], heights, outline[2]};
        return {outline[0] * heights, heights, outline[2] * heights};
    }
    // A side point (linear sweep) is a weighted sum of a segment's points
    // (|weights| summing to 1 for linear and Bezier segments, at most 2.25
    // for quadratic and cubic ones) at a height; a conic sweep scales it by
    // the height: |y f - y0 f0| <= |y - y0| |f| + |y0| |f - f0|. Cap points
    // follow the outline.
    double surface_motion(const Interval& t, const Geometry& mid) const {
        (void)mid;
        double points = 0.0;
        for (const auto& p : points_) points = std::max(points, deviation(p, t, p.at(t.mid())));
        const double weights =
            spline_ == geometry::PrismSpline::linear || spline_ == geometry::PrismSpline::bezier
                ? 1.0
                : 2.25;
        const double heights = std::max(deviation(height1_, t, height1_.at(t.mid())),
                                        deviation(height2_, t, height2_.at(t.mid())));
        if (sweep_ == geometry::PrismSweep::linear) return weights * points + heights;
        const IntervalBox outline = outline_over(t);
        const double reach = outline[0].magnitude() + outline[2].magnitude();
        const double y = hull(height1_.over(t), height2_.over(t)).magnitude();
        // Rounded up by a few ulps: the bound's own arithmetic.
        return (heights * (1.0 + reach) + y * weights * points) * (1.0 + 1e-15);
    }
    // Nested outlines under the even-odd rule: sampled by the caller.
    static double volume(const Geometry&) { return -1.0; }

  private:
    IntervalBox outline_over(const Interval& t) const {
        std::vector<IntervalBox> ranges;
        ranges.reserve(points_.size());
        for (const auto& p : points_) ranges.push_back(p.over(t));
        IntervalBox box = empty_interval_box();
        if (spline_ == geometry::PrismSpline::linear || ranges.empty()) {
            for (const auto& r : ranges) box = hull(box, r);
            return box;
        }
        const std::size_t width = spline_ == geometry::PrismSpline::quadratic ? 3 : 4;
        const std::size_t step = spline_ == geometry::PrismSpline::bezier ? 4 : 1;
        for (std::size_t i = 0; i + width <= ranges.size(); i += step) {
            // lathe_polynomial's point j of segment s is point 4 s + j for
            // Bezier splines, s + j for the others.
            const int segment =
                static_cast<int>(spline_ == geometry::PrismSpline::bezier ? i / 4 : i);
            const auto p = geometry::lathe_polynomial<Interval>(
                spline_, segment,
                [&](int j, int k) { return ranges[static_cast<std::size_t>(j)][k == 0 ? 0 : 2]; });
            box[0] = hull(box[0], geometry::lathe_control_hull(p, 0));
            box[2] = hull(box[2], geometry::lathe_control_hull(p, 1));
        }
        if (box[0].is_empty()) return {Interval(0.0), Interval(0.0), Interval(0.0)};
        box[1] = Interval(0.0);
        return box;
    }

    CompiledScalar height1_, height2_;
    std::vector<CompiledVector3> points_;
    bool open_;
    geometry::PrismSpline spline_;
    geometry::PrismSweep sweep_;
    bool is_static_ = true;
};

}  // namespace hexant::runtime::objects
