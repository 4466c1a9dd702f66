// Iridescence: a thin film's interference on the light a surface sends to
// the eye, POV-Ray 3.7's ComputeIridColour (trace.cpp, "DMF"). The phase
// offset grows with the film's thickness (wobbled by turbulence) and the
// sum of the light's and the eye's angle cosines; each channel is scaled by
// 1 + amount * cos(offset / its wavelength).
#pragma once

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "runtime/texture/material_sample.hpp"
#include "runtime/texture/pattern/noise.hpp"

namespace hexant::tracer {

// The factor for light arriving along `to_light` (unit, toward the light;
// for a reflection, the reflected ray's direction) and leaving along -eye
// (`eye`: the view ray's unit direction), at world point `point` with
// shading normal `normal`. `wavelengths`: global_settings' irid_wavelength.
inline glm::dvec3 iridescence(const runtime::MaterialSample& m, const glm::dvec3& to_light,
                              const glm::dvec3& eye, const glm::dvec3& normal,
                              const glm::dvec3& point, const glm::dvec3& wavelengths,
                              int noise_generator) {
    double thickness = m.irid_thickness;
    if (m.irid_turbulence != 0.0) {
        // POV-Ray's fixed turbulence: 5 octaves, omega 0.5, lambda 2; a
        // value of 0..1 turned into 1 +- the amount.
        static const runtime::pattern::Octaves kOctaves =
            runtime::pattern::octaves_of(5.0, 0.5, 2.0);
        const double noise =
            2.0 * runtime::pattern::turbulence(point, kOctaves, noise_generator) - 1.0;
        thickness *= 1.0 + noise * m.irid_turbulence;
    }
    const double cosines = std::fabs(glm::dot(normal, to_light)) + std::fabs(glm::dot(normal, eye));
    const double interference = 2.0 * std::numbers::pi * thickness * cosines;
    glm::dvec3 factor;
    for (int k = 0; k < 3; ++k) factor[k] = 1.0 + m.irid * std::cos(interference / wavelengths[k]);
    return factor;
}

}  // namespace hexant::tracer
