// POV-Ray's f_noise3d(x, y, z) and f_noise_generator(x, y, z, G) (its
// fnintern.cpp: Noise at the point, with the scene's generator or G & 3)
// as a function a user function calls (runtime/time/point_function.hpp).
// It bounds itself, so an isosurface may use it: over a box, the noise at
// the box's centre plus or minus its slope bound (noise_slope_bound) times
// the half-widths, within [0, 1]; its gradient is the noise's own.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>

#include "runtime/texture/pattern/noise.hpp"
#include "runtime/time/point_function.hpp"

namespace hexant::runtime::pattern {

class NoiseFunction final : public PointFunction {
  public:
    // generator: 1, 2 or 3 (POV-Ray's noise_generator); 0 reads as 1, as
    // POV-Ray's (G & 3) does for a G of 4.
    explicit NoiseFunction(int generator) : generator_(generator < 1 ? 1 : generator) {}

    std::string name() const override { return "f_noise3d"; }
    int components() const override { return 1; }
    bool depends_on_time() const override { return false; }
    double at(int, const glm::dvec3& p, double) const override { return noise(p, generator_); }
    bool bounded() const override { return true; }
    Interval over(int, const std::array<Interval, 3>& p, const Interval&) const override {
        glm::dvec3 centre;
        double reach = 0.0;
        for (int i = 0; i < 3; ++i) {
            if (!std::isfinite(p[i].lo) || !std::isfinite(p[i].hi)) return {0.0, 1.0};
            centre[i] = p[i].lo + (p[i].hi - p[i].lo) / 2;
            reach += std::max(centre[i] - p[i].lo, p[i].hi - centre[i]);
        }
        // (1e-9: the noise's own rounding, and the lattice's 1e-10 step at
        // negative integers, POV-Ray's EPSILON, are far below it.)
        const double slack = noise_slope_bound(generator_) * reach * (1.0 + 1e-12) + 1e-9;
        const double v = noise(centre, generator_);
        return {std::max(0.0, v - slack), std::min(1.0, v + slack)};
    }
    std::array<double, 4> gradient(int, const glm::dvec3& p, double) const override {
        const glm::dvec3 g = noise_gradient(p, generator_);
        return {g.x, g.y, g.z, 0.0};
    }

  private:
    int generator_;
};

}  // namespace hexant::runtime::pattern
