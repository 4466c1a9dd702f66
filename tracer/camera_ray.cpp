#include "tracer/camera_ray.hpp"

#include <cmath>

namespace hexant::tracer {

namespace camera_ray_detail {

constexpr double kPi = 3.14159265358979323846;
constexpr double kEpsilon = 1.0e-10;   // POV-Ray's EPSILON
constexpr double kBoundHuge = 2.0e10;  // POV-Ray's BOUND_HUGE

// v turned by `angle` radians about the unit axis k (Rodrigues; POV-Ray's
// Compute_Axis_Rotation_Transform turns +x toward +y about +z, as this).
inline glm::dvec3 rotate(const glm::dvec3& v, const glm::dvec3& k, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    return v * c + glm::cross(k, v) * s + k * (glm::dot(k, v) * (1.0 - c));
}

}  // namespace camera_ray_detail

std::optional<ScreenRay> projected_camera_ray(const runtime::CameraFrame& camera, double x0,
                                              double y0) {
    using namespace camera_ray_detail;
    using runtime::CameraType;
    switch (camera.type) {
        case CameraType::Orthographic:
            // Parallel rays across a film of right by up.
            return ScreenRay{
                camera.location + x0 * camera.right + y0 * camera.up, camera.direction, {x0, y0}};
        case CameraType::Fisheye: {
            // The screen from -1 to 1 scaled by right's and up's lengths; the
            // unit circle holds the view, its radius the angle off the view
            // (half the camera's angle at the rim).
            const double x = 2.0 * x0 * glm::length(camera.right),
                         y = 2.0 * y0 * glm::length(camera.up);
            const double rad = std::sqrt(x * x + y * y);
            if (rad > 1.0) return std::nullopt;
            const double phi = rad == 0.0 ? 0.0
                               : x < 0.0  ? kPi - std::asin(y / rad)
                                          : std::asin(y / rad);
            const double theta = rad * camera.angle * kPi / 360.0;
            const glm::dvec3 right = glm::normalize(camera.right), up = glm::normalize(camera.up);
            const glm::dvec3 direction = glm::normalize(camera.direction);
            return ScreenRay{camera.location,
                             std::cos(phi) * std::sin(theta) * right +
                                 std::sin(phi) * std::sin(theta) * up + std::cos(theta) * direction,
                             {phi, theta}};
        }
        case CameraType::Panoramic: {
            // Graphics Gems III's: 180 degrees across (angle unused, as in
            // POV-Ray), a cylinder's height by the tangent up and down.
            const double across = (1.0 - (x0 + 0.5)) * kPi, height = kPi / 2.0 * (2.0 * y0);
            const double ty = std::fabs(kPi / 2.0 - std::fabs(height)) < kEpsilon
                                  ? (height > 0.0 ? kBoundHuge : -kBoundHuge)
                                  : std::tan(height);
            return ScreenRay{camera.location,
                             std::cos(across) * camera.right + ty * camera.up +
                                 std::sin(across) * camera.direction,
                             {across, height}};
        }
        case CameraType::Spherical: {
            // Latitude about right, then longitude about up.
            const double latitude = y0 * camera.v_angle / 360.0 * 2.0 * kPi;
            const double longitude = x0 * camera.h_angle / 360.0 * 2.0 * kPi;
            const glm::dvec3 tilted =
                rotate(camera.direction, glm::normalize(camera.right), -latitude);
            return ScreenRay{camera.location,
                             rotate(tilted, glm::normalize(camera.up), longitude),
                             {longitude, latitude}};
        }
        case CameraType::Perspective:
            // (camera_ray makes the pinhole's own.)
            return ScreenRay{
                camera.location, camera.direction + x0 * camera.right + y0 * camera.up, {x0, y0}};
    }
    return std::nullopt;
}

}  // namespace hexant::tracer
