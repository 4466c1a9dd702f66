// POV-Ray 3.7's primary rays (TracePixel::CreateCameraRay, tracepixel.cpp)
// for the projections hexant makes: perspective, orthographic, fisheye,
// panoramic, spherical, ultra_wide_angle, omnimax and cylinder 1 to 4. A screen point is (x0, y0)
// in [-0.5, 0.5]^2, x to the right and y up, as POV-Ray forms it from the pixel; each projection
// turns it into an origin and a direction (not normalized: the focal blur scales it first, as
// POV-Ray's JitterCameraRay does), or into no ray (a fisheye's corners, outside its circle: POV-Ray
// leaves those samples black).
#pragma once

#include <cmath>
#include <optional>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "runtime/scene/camera.hpp"
#include "runtime/texture/texture_evaluator.hpp"
#include "tracer/focal_blur.hpp"

namespace hexant::tracer {

struct ScreenRay {
    glm::dvec3 origin, direction;
    // Where a camera's normal { } pattern is evaluated: POV-Ray's (x0, y0)
    // as the projection leaves them (perspective and orthographic: the
    // screen point; fisheye: its polar angle and the ray's angle off the
    // view; panoramic and spherical: the angles in radians).
    glm::dvec2 pattern_point;
};

// The wide and parallel projections (camera_ray.cpp).
std::optional<ScreenRay> projected_camera_ray(const runtime::CameraFrame& camera, double x0,
                                              double y0);

// The ray through screen point (x0, y0) into `out`, or false for none; the
// pinhole's inline, as every sample of the usual camera asks. (Filled in
// place: an optional copied out of an inlined call became 16-byte moves
// over 24-byte vectors, whose stores the loads after them could not
// forward, a stall on every sample.)
[[gnu::always_inline]] inline bool camera_ray(const runtime::CameraFrame& camera, double x0,
                                              double y0, ScreenRay& out) {
    if (camera.type == runtime::CameraType::Perspective) {
        out.origin = camera.location;
        out.direction = camera.direction + x0 * camera.right + y0 * camera.up;
        out.pattern_point = {x0, y0};
        return true;
    }
    const std::optional<ScreenRay> ray = projected_camera_ray(camera, x0, y0);
    if (!ray) return false;
    out = *ray;
    return true;
}

// A sample's primary ray, in POV-Ray's order (CreateCameraRay): the
// projection's ray through screen point (x0, y0); with an aperture, moved
// to the lens point that lens() (a pair in [0, 1)^2) picks (focal_blur.hpp),
// the origin moving with it; then bent by the camera's normal { } at its
// screen point, at time t, when there is one. The direction is unit.
// False, `out` unset, where the projection gives no ray.
struct PrimaryRay {
    glm::dvec3 origin, direction;
};

template <class Lens>
[[gnu::always_inline]] inline bool primary_ray(const runtime::CameraFrame& camera, double x0,
                                               double y0, Lens&& lens,
                                               const runtime::TextureEvaluator* normal, double t,
                                               PrimaryRay& out) {
    ScreenRay screen;
    if (!camera_ray(camera, x0, y0, screen)) return false;
    out.origin = screen.origin;
    if (camera.aperture != 0.0) {
        // (The lens moves an orthographic ray's own origin, where POV-Ray
        // 3.7 moves every ray's to the location's lens.)
        const CameraRay ray = focal_blur_ray(camera, screen.direction, lens_point(lens()));
        out.origin = out.origin - camera.location + ray.origin;
        out.direction = ray.direction;
    } else {
        out.direction = glm::normalize(screen.direction);
    }
    if (normal) out.direction = normal->perturb(out.direction, {screen.pattern_point, 0.0}, t);
    return true;
}

// Calls add(p) with every point a camera's rays start from or that bounds
// them at time t: the location, the lens around it (focal blur) and,
// orthographic, the film's corners (cylinder 3 and 4: the film's edge along
// the axis); a mesh camera's box around its meshes' faces.
template <class Add>
void eye_extent(const runtime::CameraFrame& camera, double t, Add&& add) {
    add(camera.location);
    if (camera.mesh) camera.mesh->origin_extent(camera.location.z, t, add);
    const double r = std::fabs(camera.aperture) / 4.0;
    glm::dvec3 spread(r);
    if (camera.type == runtime::CameraType::Orthographic)
        spread += 0.5 * (glm::abs(camera.right) + glm::abs(camera.up));
    if (camera.type == runtime::CameraType::Cylinder3) spread += 0.5 * glm::abs(camera.up);
    if (camera.type == runtime::CameraType::Cylinder4) spread += 0.5 * glm::abs(camera.right);
    if (spread != glm::dvec3(0.0)) {
        add(camera.location - spread);
        add(camera.location + spread);
    }
}

}  // namespace hexant::tracer
