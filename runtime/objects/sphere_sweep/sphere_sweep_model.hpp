// The sphere sweep's time functions: its spheres' centres and radii.
#pragma once

#include <algorithm>
#include <limits>
#include <vector>

#include "runtime/objects/model_support.hpp"
#include "runtime/objects/sphere_sweep/sphere_sweep.hpp"
#include "runtime/objects/sphere_sweep/sphere_sweep_geometry.hpp"

namespace hexant::runtime::objects {

class SphereSweepModel {
  public:
    using Geometry = geometry::SphereSweepGeometry;
    static constexpr bool kSolid = true;

    explicit SphereSweepModel(const SphereSweep& s) : spline_(s.spline) {
        const std::size_t n = std::min(s.centres.size(), s.radii.size());
        centres_.reserve(n);
        radii_.reserve(n);
        for (std::size_t i = 0; i < n; ++i) {
            centres_.emplace_back(s.centres[i]);
            radii_.emplace_back(s.radii[i]);
            is_static_ = is_static_ && centres_.back().is_constant() && radii_.back().is_constant();
        }
    }

    bool is_static() const { return is_static_; }
    Geometry at(double t) const {
        std::vector<glm::dvec3> centres;
        std::vector<double> radii;
        centres.reserve(centres_.size());
        radii.reserve(radii_.size());
        for (const auto& c : centres_) centres.push_back(c.at(t));
        for (const auto& r : radii_) radii.push_back(r.at(t));
        return geometry::make_sphere_sweep(spline_, centres, radii);
    }
    // Each segment's polynomials with interval coefficients (the spheres'
    // ranges over t, POV-Ray's matrices in outward-rounded arithmetic), then
    // their Bernstein control points, whose hull holds the segment's centres
    // and radii for every u in [0, 1] (a Catmull-Rom segment overshoots its
    // spheres; its control hull does not); the box is that of the centres
    // widened by the largest |radius|.
    IntervalBox box_over(const Interval& t) const {
        const std::size_t n = centres_.size();
        std::vector<std::array<Interval, 4>> ranges(n);
        for (std::size_t i = 0; i < n; ++i) {
            const IntervalBox c = centres_[i].over(t);
            ranges[i] = {c[0], c[1], c[2], radii_[i].over(t)};
        }
        const int count = geometry::sphere_sweep_segment_count(spline_, n);
        if (count <= 0) return {Interval(0.0), Interval(0.0), Interval(0.0)};
        IntervalBox box = empty_interval_box();
        const Interval third = Interval(1.0) / Interval(3.0);
        for (int i = 0; i < count; ++i) {
            Interval p[4][4];
            geometry::sphere_sweep_polynomial<Interval>(
                spline_, i, [&](int j, int k) { return ranges[static_cast<std::size_t>(j)][k]; },
                p);
            Interval hulls[4];
            for (int k = 0; k < 4; ++k) {
                const Interval b0 = p[0][k];
                const Interval b1 = p[0][k] + p[1][k] * third;
                const Interval b2 = p[0][k] + (Interval(2.0) * p[1][k] + p[2][k]) * third;
                const Interval b3 = p[0][k] + p[1][k] + p[2][k] + p[3][k];
                hulls[k] = hull(hull(b0, b1), hull(b2, b3));
            }
            const Interval radius(0.0, hulls[3].magnitude());
            box = hull(box, ball_box({hulls[0], hulls[1], hulls[2]}, radius));
        }
        return box;
    }
    // A sphere of a segment has centre and radius sum_j w_j(u) S_j, so the
    // union of balls moves (Hausdorff) by at most sum |w_j| (1 for linear
    // and B-spline segments, 1.25 for Catmull-Rom ones) times the largest
    // deviation of a centre plus that of a radius.
    double surface_motion(const Interval& t, const Geometry& mid) const {
        (void)mid;
        if (is_static_) return 0.0;
        const double tm = t.mid();
        double centre = 0.0, radius = 0.0;
        for (const auto& c : centres_) centre = std::max(centre, deviation(c, t, c.at(tm)));
        for (const auto& r : radii_) radius = std::max(radius, deviation(r, t, r.at(tm)));
        const double weights = spline_ == geometry::SweepSpline::cubic ? 1.25 : 1.0;
        return std::nextafter(weights * (centre + radius) * (1.0 + 8.0 * 1.1102230246251565e-16),
                              std::numeric_limits<double>::infinity());
    }
    // Sampled by the caller (the spheres overlap).
    static double volume(const Geometry&) { return -1.0; }

  private:
    geometry::SweepSpline spline_;
    std::vector<CompiledVector3> centres_;
    std::vector<CompiledScalar> radii_;
    bool is_static_ = true;
};

}  // namespace hexant::runtime::objects
