// POV-Ray 3.7's perspective camera (language version 3.5 and later).
//
// POV-Ray does NOT apply the camera's items in the order written. It reads
// them all (a repeated item replaces the earlier value; transforms compose in
// the order written), then builds the camera in a fixed order:
//   1. start from the defaults (location <0,0,0>, direction <0,0,1>,
//      right <1.33,0,0>, up <0,1,0>, sky <0,1,0>) overridden by the values
//      given for location, direction, right, up and sky;
//   2. angle A (if given and > 0): direction keeps its line but gets length
//      |right| / (2 tan(A/2)); A must be < 180;
//   3. look_at P (if given): with the lengths |direction|, |up|, |right| and
//      the handedness sign of (up x direction) . right taken from step 2,
//        direction = normalize(P - location)       (error if P == location)
//        right     = normalize(sky x direction)    (kept as it was, then
//                    normalized, if sky is parallel to direction)
//        up        = direction x right
//      then direction, up and right get back their lengths, right with its
//      sign flipped when the handedness was not positive;
//   4. orthographic only: when neither up nor right was given, or an angle
//      was, right and up are scaled by |look_at - location| / |direction|
//      (look_at's default <0, 0, 1> when none was given), so that the view
//      covers what the perspective one would at look_at;
//   5. the transforms, composed in order, move location as a point and
//      direction, up and right as directions (no translation). sky and
//      look_at are not moved.
// The projection (perspective, orthographic, fisheye, panoramic,
// spherical) comes first in the block; only perspective and orthographic
// cameras' angle sets direction's length (Parse_Camera, parse.cpp).
// This record keeps the items in the order written; evaluate() applies the
// rules above at time t.
#include "runtime/scene/camera.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

namespace hexant::runtime {

namespace {

constexpr double kEpsilon = 1.0e-10;  // POV-Ray's EPSILON
constexpr double kPi = 3.14159265358979323846;

}  // namespace

bool CameraRecord::depends_on_time() const {
    if (!pieces.empty()) return true;
    for (const CameraItem& item : items) {
        switch (item.kind) {
            case CameraItem::Kind::Angle:
            case CameraItem::Kind::VerticalAngle:
            case CameraItem::Kind::Aperture:
            case CameraItem::Kind::BlurSamples:
                if (item.angle.depends_on_time()) return true;
                break;
            case CameraItem::Kind::Type:
                break;
            case CameraItem::Kind::Transform:
                if (item.step.depends_on_time()) return true;
                break;
            default:
                if (item.vector.depends_on_time()) return true;
                break;
        }
    }
    return false;
}

CameraFrame CameraRecord::evaluate(double t) const {
    for (const Piece& piece : pieces)
        if (piece.when.contains(t)) return evaluate_items(piece.items, t);
    return evaluate_items(items, t);
}

CameraFrame CameraRecord::evaluate_items(const std::vector<CameraItem>& items, double t) {
    CameraFrame cam;  // POV-Ray's defaults
    bool has_look_at = false, has_angle = false;
    glm::dvec3 look_at{0, 0, 1};
    double angle = 0.0;
    glm::dmat4 transform(1.0);
    bool has_transform = false;
    std::optional<glm::dvec3> focal_point;
    double blur_samples = 0.0;
    bool has_up = false, has_right = false;
    std::optional<double> vertical_angle;

    // 1. Gather: the last value of each item wins; transforms compose.
    for (const CameraItem& item : items) {
        switch (item.kind) {
            case CameraItem::Kind::Location:
                cam.location = item.vector(t);
                break;
            case CameraItem::Kind::Direction:
                cam.direction = item.vector(t);
                break;
            case CameraItem::Kind::Right:
                cam.right = item.vector(t);
                has_right = true;
                break;
            case CameraItem::Kind::Up:
                cam.up = item.vector(t);
                has_up = true;
                break;
            case CameraItem::Kind::Sky:
                cam.sky = item.vector(t);
                break;
            case CameraItem::Kind::LookAt:
                look_at = item.vector(t);
                has_look_at = true;
                break;
            case CameraItem::Kind::Angle:
                angle = item.angle(t);
                has_angle = true;
                break;
            case CameraItem::Kind::Transform:
                transform = item.step.matrix_at(t) * transform;
                has_transform = true;
                break;
            case CameraItem::Kind::Aperture:
                cam.aperture = item.angle(t);
                break;
            case CameraItem::Kind::FocalPoint:
                focal_point = item.vector(t);
                break;
            case CameraItem::Kind::BlurSamples:
                blur_samples = item.angle(t);
                break;
            case CameraItem::Kind::Type:
                cam.type = item.type;
                cam.mesh = item.mesh;
                break;
            case CameraItem::Kind::VerticalAngle:
                vertical_angle = item.angle(t);
                break;
        }
    }
    const bool flat = cam.type == CameraType::Perspective || cam.type == CameraType::Orthographic;
    // (POV-Ray's Direction_Length: the focal distance without a
    // focal_point; 1 unless angle or look_at set it.)
    double direction_length = 1.0;

    // 2. angle sets the direction's length from right's (perspective and
    // orthographic); the other projections keep their angles.
    if (has_angle) {
        if (angle < 0.0) throw std::domain_error("camera: negative viewing angle");
        if (flat && angle >= 180.0)
            throw std::domain_error("camera: viewing angle has to be smaller than 180 degrees");
        if (flat && angle > 0.0) {
            direction_length = glm::length(cam.right) / std::tan(angle * kPi / 360.0) / 2.0;
            cam.direction = glm::normalize(cam.direction) * direction_length;
        }
        if (!flat && cam.type != CameraType::Spherical) cam.angle = angle;
        if (cam.type == CameraType::Spherical) {
            cam.h_angle = angle;
            cam.v_angle = vertical_angle ? *vertical_angle : angle * 0.5;
            if (cam.v_angle < 0.0) throw std::domain_error("camera: negative vertical angle");
        }
    }

    // 3. look_at turns the camera, keeping the lengths and the handedness.
    if (has_look_at) {
        direction_length = glm::length(cam.direction);
        const double up_length = glm::length(cam.up);
        const double right_length = glm::length(cam.right);
        const double handedness = glm::dot(glm::cross(cam.up, cam.direction), cam.right);

        // POV-Ray refuses a look_at closer than 1e-5 to the location (its
        // squared distance under EPSILON); hexant only one that is not
        // apart at all, so that a scene modelled at any scale (a world of
        // micrometres) keeps its camera. The sky test is relative to the
        // sky's length for the same reason.
        glm::dvec3 direction = look_at - cam.location;
        const double distance = glm::length(direction);
        if (!(distance > 0.0) || !std::isfinite(distance))
            throw std::domain_error("camera: location and look_at point must be different");
        direction /= distance;

        glm::dvec3 right = glm::cross(cam.sky, direction);
        if (!(glm::length(right) > kEpsilon * glm::length(cam.sky)))
            right = cam.right;  // sky parallel to the view: keep the old right
        right = glm::normalize(right);

        cam.up = glm::cross(direction, right) * up_length;
        cam.direction = direction * direction_length;
        cam.right = right * (handedness > 0.0 ? right_length : -right_length);
    }

    // 4. An orthographic view as wide at look_at as the perspective one.
    if (cam.type == CameraType::Orthographic && ((!has_up && !has_right) || has_angle)) {
        const double k1 = glm::length(look_at - cam.location), k2 = glm::length(cam.direction);
        if (k1 > kEpsilon && k2 > kEpsilon) {
            cam.right *= k1 / k2;
            cam.up *= k1 / k2;
        }
    }

    // Focal blur when both an aperture and samples are given (POV-Ray's
    // useFocalBlur); in focus at focal_point's distance, else at POV-Ray's
    // Direction_Length (a length 0 counts as 1, as there).
    // (A mesh camera's rays are its faces', whatever the aperture: POV-Ray
    // traces the same rays however many times its focal blur asks.)
    if (!(blur_samples > 0.0) || cam.type == CameraType::Mesh) cam.aperture = 0.0;
    cam.focal_distance = focal_point ? glm::length(*focal_point - cam.location) : direction_length;
    if (cam.focal_distance == 0.0) cam.focal_distance = 1.0;

    // 5. The transforms, last.
    if (has_transform) {
        const glm::dmat3 linear(transform);
        cam.location = glm::dvec3(transform * glm::dvec4(cam.location, 1.0));
        cam.direction = linear * cam.direction;
        cam.up = linear * cam.up;
        cam.right = linear * cam.right;
    }
    return cam;
}

}  // namespace hexant::runtime
