// The sor's time functions: its points (<radius, height>).
#pragma once

#include <algorithm>
#include <limits>
#include <vector>

#include "runtime/objects/model_support.hpp"
#include "runtime/objects/sor/sor.hpp"
#include "runtime/objects/sor/sor_geometry.hpp"

namespace hexant::runtime::objects {

class SorModel {
  public:
    using Geometry = geometry::SorGeometry;
    static constexpr bool kSolid = true;
    static constexpr bool kUvMapping = true;  // POV-Ray 3.7 maps it (primitive.hpp)

    explicit SorModel(const Sor& s) : open_(s.open) {
        points_.reserve(s.points.size());
        for (const auto& point : s.points) {
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
        return geometry::make_sor(points, open_);
    }
    // Per segment, r^2 in Hermite form over s in [0, 1]: x1^2 h00 + x2^2 h01 +
    // h (k2 h10 + k3 h11), |h00|, |h01| <= 1 and |h10|, |h11| <= 4/27, in
    // outward-rounded intervals over the points' ranges (a slope whose height
    // difference may be 0 is unbounded: then so is the box), plus POV-Ray's
    // snapping of coefficients below 1e-10 (at most 1e-10 (1 + |y| + y^2 +
    // |y|^3) of r^2). Heights: those of P[1] .. P[N-2].
    IntervalBox box_over(const Interval& t) const {
        const std::size_t n = points_.size();
        if (n < 4) return {Interval(0.0), Interval(0.0), Interval(0.0)};
        std::vector<IntervalBox> p;
        p.reserve(n);
        for (const auto& q : points_) p.push_back(q.over(t));
        Interval height(std::numeric_limits<double>::infinity(),
                        -std::numeric_limits<double>::infinity());
        for (std::size_t i = 1; i + 1 < n; ++i) height = hull(height, p[i][1]);
        const double ymax = height.magnitude();
        const double snap = 1e-10 * (1.0 + ymax + ymax * ymax + ymax * ymax * ymax) * 1.01;
        double r2 = 0.0;
        for (std::size_t i = 0; i + 3 < n; ++i) {
            const Interval k0 = sqr(p[i + 1][0]), k1 = sqr(p[i + 2][0]);
            const Interval k2 =
                Interval(2.0) * p[i + 1][0] * ((p[i + 2][0] - p[i][0]) / (p[i + 2][1] - p[i][1]));
            const Interval k3 = Interval(2.0) * p[i + 2][0] *
                                ((p[i + 3][0] - p[i + 1][0]) / (p[i + 3][1] - p[i + 1][1]));
            const Interval h = p[i + 2][1] - p[i + 1][1];
            const Interval bound = k0.magnitude() + k1.magnitude() +
                                   Interval(4.0 / 27.0 * 1.0000001) * h.magnitude() *
                                       (k2.magnitude() + k3.magnitude());
            r2 = std::max(r2, bound.hi);
        }
        const double radius = std::nextafter(std::sqrt(r2 + snap) * (1.0 + 1e-15),
                                             std::numeric_limits<double>::infinity());
        const Interval across(-radius, radius);
        return {across, height, across};
    }
    // Any surface point over t and the surface at the middle instant both lie
    // in box_over(t): its diagonal bounds how far the surface moves (loose;
    // r = sqrt of a cubic whose coefficients divide by height differences has
    // no simple tighter bound).
    double surface_motion(const Interval& t, const Geometry& mid) const {
        (void)mid;
        if (is_static_) return 0.0;
        const IntervalBox b = box_over(t);
        double sum = 0.0;
        for (int i = 0; i < 3; ++i) sum += b[i].width() * b[i].width();
        return std::sqrt(sum) * (1.0 + 1e-15);
    }
    static double volume(const Geometry&) { return -1.0; }

  private:
    std::vector<CompiledVector3> points_;
    bool open_;
    bool is_static_ = true;
};

}  // namespace hexant::runtime::objects
