// The torus's time functions: major and minor radius.
#pragma once

#include <numbers>

#include "runtime/objects/model_support.hpp"
#include "runtime/objects/torus/torus.hpp"
#include "runtime/objects/torus/torus_geometry.hpp"

namespace hexant::runtime::objects {

class TorusModel {
  public:
    using Geometry = geometry::TorusGeometry;
    static constexpr bool kSolid = true;
    static constexpr bool kUvMapping = true;  // POV-Ray 3.7 maps it (primitive.hpp)

    explicit TorusModel(const Torus& t) : major_(t.major_radius), minor_(t.minor_radius) {}

    bool is_static() const { return major_.is_constant() && minor_.is_constant(); }
    Geometry at(double t) const { return {major_.at(t), minor_.at(t)}; }
    IntervalBox box_over(const Interval& t) const {
        const double r = std::max(minor_.over(t).hi, 0.0);
        const double outer = std::max(major_.over(t).hi, 0.0) + r;
        return {Interval(-outer, outer) * Interval(1.0, 1.0 + 1e-15), Interval(-r, r),
                Interval(-outer, outer) * Interval(1.0, 1.0 + 1e-15)};
    }
    // A surface point (R + r cos a, r sin a) in its meridian plane moves by at
    // most |dR| + |dr| when the radii change.
    double surface_motion(const Interval& t, const Geometry& mid) const {
        return deviation(major_, t, mid.major) + deviation(minor_, t, mid.minor);
    }
    // Pappus; a spindle torus (minor > major) has no closed form here: the
    // caller samples (a negative volume means unknown).
    static double volume(const Geometry& g) {
        if (g.minor <= 0.0 || g.major < 0.0) return 0.0;
        if (g.minor > g.major) return -1.0;
        return 2.0 * std::numbers::pi * std::numbers::pi * g.major * g.minor * g.minor;
    }

  private:
    CompiledScalar major_, minor_;
};

}  // namespace hexant::runtime::objects
