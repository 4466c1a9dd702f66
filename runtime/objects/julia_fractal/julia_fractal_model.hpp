// The julia_fractal's time functions: its parameter c, its slice and the
// slice's distance, pwr's exponent.
#pragma once

#include <array>
#include <cmath>
#include <limits>

#include "runtime/objects/julia_fractal/julia_fractal.hpp"
#include "runtime/objects/julia_fractal/julia_fractal_geometry.hpp"
#include "runtime/objects/model_support.hpp"

namespace hexant::runtime::objects {

class JuliaFractalModel {
  public:
    using Geometry = geometry::JuliaFractalGeometry;
    static constexpr bool kSolid = true;

    explicit JuliaFractalModel(const JuliaFractal& j)
        : algebra_(j.algebra),
          function_(j.function),
          iterations_(j.iterations),
          precision_(j.precision),
          slice_distance_(j.slice_distance) {
        for (int i = 0; i < 4; ++i) {
            c_[i] = CompiledScalar(j.parameter[i]);
            slice_[i] = CompiledScalar(j.slice[i]);
        }
        for (int i = 0; i < 2; ++i) exponent_[i] = CompiledScalar(j.exponent[i]);
    }

    bool is_static() const {
        bool fixed = slice_distance_.is_constant() && exponent_[0].is_constant() &&
                     exponent_[1].is_constant();
        for (int i = 0; i < 4; ++i) fixed = fixed && c_[i].is_constant() && slice_[i].is_constant();
        return fixed;
    }
    Geometry at(double t) const {
        std::array<double, 4> c, slice;
        for (int i = 0; i < 4; ++i) {
            c[i] = c_[i].at(t);
            slice[i] = slice_[i].at(t);
        }
        return geometry::make_julia_fractal(c, algebra_, function_,
                                            {exponent_[0].at(t), exponent_[1].at(t)}, iterations_,
                                            precision_, slice, slice_distance_.at(t));
    }
    // The ball no inside point leaves (julia_reach), over the times: a
    // quaternion's radius grows with |c| up to 2 (Compute_BBox), a
    // hypercomplex one's is 4.
    IntervalBox box_over(const Interval& t) const {
        double r = 4.0;
        if (algebra_ == geometry::JuliaAlgebra::quaternion) {
            Interval sum(0.0);
            for (const auto& c : c_) sum += sqr(c.over(t));
            const double radius = std::min(2.0, (1.0 + sqrt(sum) + 1e-7).hi);
            r = std::isfinite(radius) ? std::sqrt(radius * radius + 1e-7) : 2.0 * (1.0 + 1e-6);
        }
        r *= 1.0 + 1e-13;  // above julia_reach's own rounding
        return {Interval(-r, r), Interval(-r, r), Interval(-r, r)};
    }
    // A set that changes may be anywhere in its ball at another instant.
    double surface_motion(const Interval& t, const Geometry&) const {
        if (is_static()) return 0.0;
        return 2.0 * std::sqrt(3.0) * box_over(t)[0].hi * (1.0 + 1e-15);
    }
    // No closed form: the caller samples.
    static double volume(const Geometry&) { return -1.0; }

  private:
    geometry::JuliaAlgebra algebra_;
    geometry::JuliaFunction function_;
    int iterations_;
    double precision_;
    std::array<CompiledScalar, 4> c_, slice_;
    std::array<CompiledScalar, 2> exponent_;
    CompiledScalar slice_distance_;
};

}  // namespace hexant::runtime::objects
