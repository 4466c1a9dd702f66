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
        case CameraType::UltraWideAngle: {
            // Dan Farmer's: both screen axes are angles, the vertical one
            // scaled by |up| / |right| (POV-Ray's aspectRatio for it).
            const double across = x0 * camera.angle * kPi / 180.0;
            const double height = y0 * camera.angle * kPi / 180.0 * glm::length(camera.up) /
                                  glm::length(camera.right);
            return ScreenRay{
                camera.location,
                std::sin(across) * glm::normalize(camera.right) +
                    std::sin(height) * glm::normalize(camera.up) +
                    std::cos(across) * std::cos(height) * glm::normalize(camera.direction),
                {across, height}};
        }
        case CameraType::Omnimax: {
            // The dome's projection: the screen from -1 to 1, widened and
            // shifted up by the aspect ratio |right| / |up| beyond 1.283458,
            // the radius mapped to the angle off the view by POV-Ray's
            // quintic; below 45 degrees under the axis no ray.
            const double aspect = glm::length(camera.right) / glm::length(camera.up);
            double x = 2.0 * x0, y = 2.0 * y0;
            if (aspect > 1.0) {
                const double a = aspect > 1.283458 ? 1.283458 : aspect;
                if (aspect > 1.283458) x *= aspect / 1.283458;
                y = (y - 1.0) / a + 1.0;
            } else {
                y /= aspect;
            }
            const double rad = std::sqrt(x * x + y * y);
            if (rad > 1.0) return std::nullopt;
            const double phi = rad == 0.0 ? 0.0
                               : x < 0.0  ? kPi - std::asin(y / rad)
                                          : std::asin(y / rad);
            const double theta =
                1.411269 * rad - 0.09439 * rad * rad * rad + 0.25674 * std::pow(rad, 5.0);
            if (std::sin(phi) * std::sin(theta) < std::tan(135.0 * kPi / 180.0) * std::cos(theta))
                return std::nullopt;
            return ScreenRay{camera.location,
                             std::cos(phi) * std::sin(theta) * glm::normalize(camera.right) +
                                 std::sin(phi) * std::sin(theta) * glm::normalize(camera.up) +
                                 std::cos(theta) * glm::normalize(camera.direction),
                             {phi, theta}};
        }
        case CameraType::Cylinder1:
        case CameraType::Cylinder2:
        case CameraType::Cylinder3:
        case CameraType::Cylinder4: {
            // POV-Ray's four cylinder cameras: the axis along up (1, 3) or
            // right (2, 4); the other screen axis an angle around it. Types
            // 1 and 2 look from the location; 3 and 4 slide the location
            // along the axis (parallel rays that way), |up| or |right| long.
            const glm::dvec3 right = glm::normalize(camera.right), up = glm::normalize(camera.up);
            const glm::dvec3 direction = glm::normalize(camera.direction);
            const bool up_axis =
                camera.type == CameraType::Cylinder1 || camera.type == CameraType::Cylinder3;
            const bool parallel =
                camera.type == CameraType::Cylinder3 || camera.type == CameraType::Cylinder4;
            if (up_axis) {
                const double around = x0 * camera.angle * kPi / 180.0;
                const double along = y0 * glm::length(camera.up);
                const glm::dvec3 turned = std::sin(around) * right + std::cos(around) * direction;
                if (parallel)
                    return ScreenRay{camera.location + along * up, turned, {around, along}};
                return ScreenRay{camera.location, turned + along * up, {around, along}};
            }
            const double around = y0 * camera.angle * kPi / 180.0;
            const double along = x0 * glm::length(camera.right);
            const glm::dvec3 turned = std::sin(around) * up + std::cos(around) * direction;
            if (parallel)
                return ScreenRay{camera.location + along * right, turned, {along, around}};
            return ScreenRay{camera.location, along * right + turned, {along, around}};
        }
        case CameraType::Mesh:
            return std::nullopt;  // (the renderer asks MeshCamera::ray)
        case CameraType::Perspective:
            // (camera_ray makes the pinhole's own.)
            return ScreenRay{
                camera.location, camera.direction + x0 * camera.right + y0 * camera.up, {x0, y0}};
    }
    return std::nullopt;
}

}  // namespace hexant::tracer
