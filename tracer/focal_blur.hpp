// POV-Ray 3.7's focal blur (TracePixel::JitterCameraRay): the eye moves
// across the lens, in the plane across the view, and the ray turns back by
// as much, so that everything at the focal distance along the view stays
// where it was and the rest blurs. POV-Ray draws the lens points from
// hexagonal grids and a disc of radius 0.5, scaled by half the aperture
// (so the lens' radius is a quarter of the aperture); hexant draws them
// uniformly over that disc, from one more pair of the pixel's samples.
#pragma once

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "runtime/scene/camera.hpp"

namespace hexant::tracer {

// A point of the disc of radius 0.5 for `u` in [0, 1)^2, uniform by area
// (Shirley and Chiu's concentric map, which keeps the sampler's strata).
inline glm::dvec2 lens_point(glm::dvec2 u) {
    const double a = 2.0 * u.x - 1.0, b = 2.0 * u.y - 1.0;
    if (a == 0.0 && b == 0.0) return {0.0, 0.0};
    constexpr double kQuarter = 3.14159265358979323846 / 4.0;
    double r, phi;
    if (std::fabs(a) > std::fabs(b)) {
        r = a;
        phi = kQuarter * (b / a);
    } else {
        r = b;
        phi = 2.0 * kQuarter - kQuarter * (a / b);
    }
    return {0.5 * r * std::cos(phi), 0.5 * r * std::sin(phi)};
}

struct CameraRay {
    glm::dvec3 origin, direction;  // direction unit
};

// The ray through the screen along `screen` (the camera's direction plus
// its share of right and up, not normalized) from the lens point `lens`
// (lens_point). Without an aperture, the pinhole ray.
inline CameraRay focal_blur_ray(const runtime::CameraFrame& camera, const glm::dvec3& screen,
                                glm::dvec2 lens) {
    if (camera.aperture == 0.0) return {camera.location, glm::normalize(screen)};
    // POV-Ray's crosshair across the view, and its deflection x - y.
    const glm::dvec3 x_perp = glm::normalize(glm::cross(camera.up, camera.direction));
    const glm::dvec3 y_perp = glm::normalize(glm::cross(camera.direction, x_perp));
    const double r = camera.aperture * 0.5;
    const glm::dvec3 deflection = x_perp * (r * lens.x) - y_perp * (r * lens.y);
    const double focal = camera.focal_distance / glm::length(camera.direction);
    return {camera.location + deflection, glm::normalize(screen * focal - deflection)};
}

}  // namespace hexant::tracer
