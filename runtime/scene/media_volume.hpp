// The media of one interior (or the atmosphere), compiled for sampling: at a
// point and time, each media's absorption, emission and scattering times its
// density there (POV-Ray 3.7's ComputeOneMediaSample, Evaluate_Density_
// Pigment). The integration along a ray is the tracer's (tracer/media.hpp).
#pragma once

#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "runtime/scene/media.hpp"
#include "runtime/texture/texture_evaluator.hpp"

namespace hexant::runtime {

class MediaVolume {
  public:
    // The media in world space (their densities' transforms end in the
    // world). Throws ObjectError for a density pattern hexant lacks.
    explicit MediaVolume(std::vector<Media> media);

    struct One {
        Media record;
        // Each density, compiled: its colour at a world point.
        std::vector<TextureEvaluator> density;
        // Whether the coefficients depend on time (else `fixed` holds them).
        bool still = true;
        glm::dvec3 absorption{0.0}, emission{0.0}, scattering{0.0};
        double eccentricity = 0.0, extinction = 1.0;
        // The coefficients at time t (the fixed ones when still).
        struct At {
            glm::dvec3 absorption, emission, scattering;
            double eccentricity, extinction;
        };
        At at(double t) const;
        At evaluate(double t) const;  // (at, never the fixed ones)
        // The product of the densities' colours at `point` (1 without one).
        glm::dvec3 density_at(const glm::dvec3& point, double t) const;
    };
    const std::vector<One>& media() const { return media_; }
    bool empty() const { return media_.empty(); }

  private:
    std::vector<One> media_;
};

}  // namespace hexant::runtime
