// The superellipsoid's time functions: its exponents e and n.
#pragma once

#include <cmath>
#include <limits>

#include "runtime/objects/model_support.hpp"
#include "runtime/objects/superellipsoid/superellipsoid.hpp"
#include "runtime/objects/superellipsoid/superellipsoid_geometry.hpp"

namespace hexant::runtime::objects {

class SuperellipsoidModel {
  public:
    using Geometry = geometry::SuperellipsoidGeometry;
    static constexpr bool kSolid = true;

    explicit SuperellipsoidModel(const Superellipsoid& s) : e_(s.e), n_(s.n) {}

    bool is_static() const { return e_.is_constant() && n_.is_constant(); }
    Geometry at(double t) const { return geometry::make_superellipsoid(e_.at(t), n_.at(t)); }
    // The unit box whatever the exponents (POV-Ray's function is at least
    // max(|x|, |y|, |z|) for exponents >= 0; others make an empty shape).
    IntervalBox box_over(const Interval&) const {
        return {Interval(-1.0, 1.0), Interval(-1.0, 1.0), Interval(-1.0, 1.0)};
    }
    // Every surface lies in the unit box: its diagonal bounds the motion.
    double surface_motion(const Interval&, const Geometry&) const {
        if (is_static()) return 0.0;
        return 3.4641016151377553;  // 2 sqrt(3), rounded up
    }
    static double volume(const Geometry& g) { return geometry::superellipsoid_volume(g); }

  private:
    CompiledScalar e_, n_;
};

}  // namespace hexant::runtime::objects
