// The lathe's time functions: its profile points (<radius, height>).
#pragma once

#include <algorithm>
#include <vector>

#include "runtime/objects/lathe/lathe.hpp"
#include "runtime/objects/lathe/lathe_geometry.hpp"
#include "runtime/objects/model_support.hpp"

namespace hexant::runtime::objects {

class LatheModel {
  public:
    using Geometry = geometry::LatheGeometry;
    static constexpr bool kSolid = true;
    static constexpr bool kUvMapping = true;  // POV-Ray 3.7 maps it (primitive.hpp)

    explicit LatheModel(const Lathe& l) : spline_(l.spline) {
        points_.reserve(l.points.size());
        for (const auto& point : l.points) {
            // <r, y> as a vector with z = 0, so one compiled form serves.
            points_.emplace_back(Vector3Function{{point.c[0], point.c[1], TimeFunction(0.0)}});
            is_static_ = is_static_ && points_.back().is_constant();
        }
    }

    bool is_static() const { return is_static_; }
    Geometry at(double t) const {
        std::vector<glm::dvec2> points;
        points.reserve(points_.size());
        for (const auto& p : points_) {
            const glm::dvec3 v = p.at(t);
            points.emplace_back(v.x, v.y);
        }
        return geometry::make_lathe(spline_, points);
    }
    // Each segment's polynomial with interval coefficients (the points'
    // ranges over t, POV-Ray's formulas in outward-rounded arithmetic), then
    // its Bernstein control points, whose hull holds the segment for every
    // t in [0, 1] (a cubic spline overshoots its points; its control hull
    // does not).
    IntervalBox box_over(const Interval& t) const {
        std::vector<IntervalBox> ranges;
        ranges.reserve(points_.size());
        for (const auto& p : points_) ranges.push_back(p.over(t));
        const int count = geometry::lathe_segment_count(spline_, points_.size());
        Interval radius(0.0), height(std::numeric_limits<double>::infinity(),
                                     -std::numeric_limits<double>::infinity());
        for (int i = 0; i < count; ++i) {
            const auto p = geometry::lathe_polynomial<Interval>(
                spline_, i, [&](int j, int k) { return ranges[static_cast<std::size_t>(j)][k]; });
            for (int k = 0; k < 2; ++k) {
                const Interval all = geometry::lathe_control_hull(p, k);
                if (k == 0)
                    radius = hull(radius, Interval(0.0, all.magnitude()));
                else
                    height = hull(height, all);
            }
        }
        if (count <= 0) return {Interval(0.0), Interval(0.0), Interval(0.0)};
        const Interval across(-radius.hi, radius.hi);
        return {across, height, across};
    }
    // A surface point at (segment parameter, angle) is a weighted sum of the
    // segment's points, so it moves by at most the sum of |weights| (1 for
    // linear and Bezier segments, at most 2.15 for quadratic and cubic ones)
    // times the largest point deviation.
    double surface_motion(const Interval& t, const Geometry& mid) const {
        (void)mid;
        double m = 0.0;
        for (const auto& p : points_) m = std::max(m, deviation(p, t, p.at(t.mid())));
        const double weights =
            spline_ == geometry::LatheSpline::linear || spline_ == geometry::LatheSpline::bezier
                ? 1.0
                : 2.25;
        return weights * m;
    }
    // Sampled by the caller (the profile may cross itself).
    static double volume(const Geometry&) { return -1.0; }

  private:
    geometry::LatheSpline spline_;
    std::vector<CompiledVector3> points_;
    bool is_static_ = true;
};

}  // namespace hexant::runtime::objects
