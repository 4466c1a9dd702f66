// The sphere's time functions: centre and radius.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "runtime/objects/model_support.hpp"
#include "runtime/objects/sphere/sphere.hpp"
#include "runtime/objects/sphere/sphere_geometry.hpp"
#include "runtime/time/interval_matrix.hpp"

namespace hexant::runtime::objects {

class SphereModel {
  public:
    using Geometry = geometry::SphereGeometry;
    static constexpr bool kSolid = true;
    static constexpr bool kConvex = true;
    static constexpr bool kUvMapping = true;  // POV-Ray 3.7 maps it (primitive.hpp)

    explicit SphereModel(const Sphere& s) : center_(s.center), radius_(s.radius) {}

    bool is_static() const { return center_.is_constant() && radius_.is_constant(); }
    Geometry at(double t) const { return {center_.at(t), radius_.at(t)}; }
    IntervalBox box_over(const Interval& t) const {
        return ball_box(center_.over(t), radius_.over(t));
    }
    // The box of the sphere g under the affine map m (exact arithmetic on
    // m's doubles): the centre's image, plus r times the length of each
    // row of m's linear part on that axis (the extent of an ellipsoid). In
    // doubles with a margin for their rounding, not in intervals: the
    // hierarchy's leaves place each object at five to nine instants (issue
    // 43), and intervals took a ninth of a swarm's render. Per axis i:
    //   - the centre c = m0 x + m1 y + m2 z + m3 is 3 products and 3 sums:
    //     no term passes through more than 4 roundings, so the computed c
    //     is within gamma_4 S of the exact one, S = |m0 x| + |m1 y| + |m2 z|
    //     + |m3| and gamma_4 = 4u / (1 - 4u) < 2.01 eps (u = eps / 2; Higham,
    //     Accuracy and Stability, 3.1; fused multiply-adds only round
    //     less). S computed the same way is at least (1 - gamma_4) S, so
    //     e = 4 eps S_computed (exact: a power of two times S) is at least
    //     3.99 eps S, twice what is needed;
    //   - a product that underflows errs absolutely, by half the smallest
    //     subnormal at most: DBL_MIN (the smallest normal) added to e pays
    //     for any number of them;
    //   - the length's root of three squares (5 roundings) is rounded up by
    //     8 ulps and r * length then up by 2 ulps, as before, so h holds r
    //     times the exact length; where the squares might underflow
    //     (their sum below 2^-900) the sum of the entries' magnitudes,
    //     never less than the length, is taken instead;
    //   - d = h + e rounded to nearest and then up one double is at least
    //     h + e, and a sum c -/+ d rounded to nearest and then moved one
    //     double outward lies outside c -/+ d (the exact sum is within half
    //     a gap of the rounded one).
    // So the box holds [C - H, C + H] per axis for the exact centre C and
    // radius term H. A NaN anywhere makes the side infinite (next_down and
    // next_up of NaN), as an interval does. Property test:
    // tests/runtime/sphere_placed_box_test.cpp.
    static IntervalBox placed_box(const Geometry& g, const AffineMap<double>& m) {
        constexpr double kEps = std::numeric_limits<double>::epsilon();
        const double r = std::max(g.radius, 0.0);
        const double p[3] = {g.center.x, g.center.y, g.center.z};
        IntervalBox out;
        for (int i = 0; i < 3; ++i) {
            const double* row = m.m[i];
            const double c = row[0] * p[0] + row[1] * p[1] + row[2] * p[2] + row[3];
            const double s = std::fabs(row[0] * p[0]) + std::fabs(row[1] * p[1]) +
                             std::fabs(row[2] * p[2]) + std::fabs(row[3]);
            const double e = 4.0 * kEps * s + std::numeric_limits<double>::min();
            const double squares = row[0] * row[0] + row[1] * row[1] + row[2] * row[2];
            const double length = squares >= 0x1p-900
                                      ? std::sqrt(squares)
                                      : std::fabs(row[0]) + std::fabs(row[1]) + std::fabs(row[2]);
            const double h = interval_detail::up(r * length * (1.0 + 8.0 * kEps), 2);
            const double d = interval_detail::next_up(h + e);
            out[i] = Interval(interval_detail::next_down(c - d), interval_detail::next_up(c + d));
        }
        return out;
    }
    double surface_motion(const Interval& t, const Geometry& mid) const {
        return deviation(center_, t, mid.center) + deviation(radius_, t, mid.radius);
    }
    // Texture coordinates of a hit, from its object-space normal (the
    // routine leaves them to this: runtime/objects/sphere/sphere_geometry.hpp).
    static glm::dvec2 uv(const glm::dvec3& object_normal) {
        return geometry::sphere_uv(object_normal);
    }
    static double volume(const Geometry& g) {
        return g.radius > 0.0 ? 4.0 / 3.0 * std::numbers::pi * g.radius * g.radius * g.radius : 0.0;
    }

  private:
    CompiledVector3 center_;
    CompiledScalar radius_;
};

}  // namespace hexant::runtime::objects
