// A ray restated near a shape: its origin moved along the ray to the point
// closest to the shape's centre, and its direction made unit length.
//
// Why: a ray from far away (1e6 sizes) carries coordinates whose ulps are
// far larger than the shape; solving for the hit from there loses those
// digits twice, in the equation's coefficients and in origin + s*direction.
// Moving the origin first costs one rounding of ulp(|moved origin|) (fma),
// after which the shape's equation has coefficients of the shape's own size
// and the hit point origin' + t*unit is accurate to ulps of the shape. When
// the origin is already within a few sizes of the shape, moving it gains
// nothing and would only add rounding to small s, so it stays.
#pragma once

#include <cmath>
#include <optional>

#include <glm/glm.hpp>

#include "runtime/geometry/ray3.hpp"
#include "runtime/geometry/stable_arithmetic.hpp"

namespace hexant::runtime::geometry {

struct LocalRay {
    glm::dvec3 origin;  // = ray.origin + s_offset * ray.direction, rounded
    glm::dvec3 unit;    // ray.direction / length
    double length;      // |ray.direction|
    double s_offset;

    // The original ray's parameter for local distance t along unit.
    double to_s(double t) const { return s_offset + t / length; }
    // Local distance for the original parameter s (rounded; callers check the
    // final s against their range exactly, this only bounds searches).
    double to_t(double s) const { return (s - s_offset) * length; }
    glm::dvec3 at(double t) const {
        return {std::fma(t, unit.x, origin.x), std::fma(t, unit.y, origin.y),
                std::fma(t, unit.z, origin.z)};
    }
};

// Moves the origin when it lies farther than kRecentreSizes * size from
// centre. No value if the direction is zero or its length is not finite.
inline constexpr double kRecentreSizes = 4.0;

inline std::optional<LocalRay> local_ray(const Ray3& ray, const glm::dvec3& centre, double size) {
    const double length = safe_length(ray.direction);
    if (!(length > 0.0) || !std::isfinite(length)) return std::nullopt;
    if (!is_finite(ray.origin)) return std::nullopt;
    LocalRay local{ray.origin, ray.direction / length, length, 0.0};
    const glm::dvec3 to_centre = centre - ray.origin;
    if (safe_length(to_centre) > kRecentreSizes * size) {
        const double s = glm::dot(to_centre, local.unit) / length;
        if (std::isfinite(s)) {
            local.s_offset = s;
            local.origin = {std::fma(s, ray.direction.x, ray.origin.x),
                            std::fma(s, ray.direction.y, ray.origin.y),
                            std::fma(s, ray.direction.z, ray.origin.z)};
        }
    }
    return local;
}

}  // namespace hexant::runtime::geometry
