// How much a finish reflects at an angle: POV-Ray 3.7's ComputeReflectivity,
// ComputeFresnel and ComputeMetallic (trace.cpp). A variable reflection
// goes from its minimum head-on to its maximum at grazing angles, by
// (1 - cos)^falloff or, with fresnel, by the Fresnel reflectance of the
// interior's ior; metallic tints it by the pigment.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/vec3.hpp>

#include "runtime/texture/material_sample.hpp"

namespace hexant::tracer {

// POV-Ray's empirical Fresnel curve for metallic: the factor that tints
// light seen at `cosine` (of the angle off the normal) by `colour`.
inline glm::dvec3 metallic_tint(double metallic, double cosine, const glm::dvec3& colour) {
    const double x = std::acos(std::clamp(cosine, -1.0, 1.0)) / (0.5 * std::numbers::pi);
    const double f = std::clamp(0.014567225 / ((x - 1.12) * (x - 1.12)) - 0.011612903, 0.0, 1.0);
    return glm::dvec3(1.0) + metallic * (1.0 - f) * (colour - glm::dvec3(1.0));
}

// The Fresnel reflectance of unpolarized light at incidence cosine
// `cosine` on a boundary of relative ior n = n2 / n1, in [0, 1]; 1 past the
// critical angle (POV-Ray's FresnelR; Hecht, Optics, 4.6).
inline double fresnel_reflectance(double cosine, double n) {
    const double g2 = n * n + cosine * cosine - 1.0;
    if (!(g2 > 0.0)) return 1.0;
    const double g = std::sqrt(g2);
    const double a = (g - cosine) / (g + cosine);
    const double b = (cosine * (g + cosine) - 1.0) / (cosine * (g - cosine) + 1.0);
    const double f = 0.5 * a * a * (1.0 + b * b);
    return std::isfinite(f) ? std::clamp(f, 0.0, 1.0) : 1.0;
}

struct Reflectivity {
    glm::dvec3 colour{0.0};  // what the reflected light is multiplied by
    double weight = 0.0;     // the reflected ray's share, for the bailout
};

// The layer's reflectivity for a view ray meeting its normal at `cosine`
// (-d . n), where the relative index of the two sides is `relative_ior`
// (n2 / n1, Inside::relative_ior; only fresnel reads it).
inline Reflectivity reflectivity(const runtime::MaterialSample& m, double cosine,
                                 double relative_ior) {
    constexpr double kEpsilon = 1e-10;  // POV-Ray's EPSILON, on fractions in [0, 1]
    const auto weight_max = [](const glm::dvec3& c) { return std::max({c.x, c.y, c.z}); };
    Reflectivity r;
    if (m.reflection_fresnel) {
        // (Without an interior the ior is 1: no Fresnel reflection, the
        // minimum; POV-Ray stops with an error there.)
        const double f = fresnel_reflectance(cosine, relative_ior);
        r.colour = f * m.reflection_max + (1.0 - f) * m.reflection;
        r.weight = weight_max(r.colour);
    } else {
        r.weight = std::max(weight_max(m.reflection_max), weight_max(m.reflection));
        const double frac = std::fabs(m.reflection_falloff - 1.0) > kEpsilon
                                ? std::pow(1.0 - cosine, m.reflection_falloff)
                                : 1.0 - cosine;
        if (std::fabs(frac) < kEpsilon)
            r.colour = m.reflection;
        else if (std::fabs(frac - 1.0) < kEpsilon)
            r.colour = m.reflection_max;
        else
            r.colour = frac * m.reflection_max + (1.0 - frac) * m.reflection;
    }
    if (m.reflection_metallic != 0.0)
        r.colour *= metallic_tint(m.reflection_metallic, cosine, m.colour);
    if (!std::isfinite(r.colour.x + r.colour.y + r.colour.z)) r.colour = glm::dvec3(0.0);
    return r;
}

// Whether the layer reflects at all (at some angle).
inline bool reflects(const runtime::MaterialSample& m) {
    return m.reflection != glm::dvec3(0.0) || m.reflection_max != glm::dvec3(0.0);
}

}  // namespace hexant::tracer
