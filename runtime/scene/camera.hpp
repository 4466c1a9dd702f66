// POV-Ray's perspective camera. POV-Ray 3.5+ gathers the camera's items (the
// last of each kind wins), then applies angle, look_at and finally the
// transforms in the order written (camera.cpp). The record keeps the items
// as written, each possibly a function of time, and evaluates them at t.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "runtime/motion/transform.hpp"
#include "runtime/scene/mesh_camera.hpp"
#include "runtime/texture/material.hpp"
#include "runtime/time/lifetime.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime {

// POV-Ray's projections (its camera types) that hexant makes rays for
// (tracer/camera_ray.hpp).
// Cylinder1..4 are POV-Ray's `cylinder 1` to `cylinder 4`.
enum class CameraType {
    Perspective,
    Orthographic,
    Fisheye,
    Panoramic,
    Spherical,
    UltraWideAngle,
    Omnimax,
    Cylinder1,
    Cylinder2,
    Cylinder3,
    Cylinder4,
    Mesh  // mesh_camera { } (runtime/scene/mesh_camera.hpp)
};

struct CameraItem {
    // (Aperture, FocalPoint, BlurSamples: POV-Ray's focal blur. Type: the
    // projection, first when given. VerticalAngle: a spherical camera's
    // second angle.)
    enum class Kind {
        Location,
        LookAt,
        Direction,
        Right,
        Up,
        Sky,
        Angle,
        Transform,
        Aperture,
        FocalPoint,
        BlurSamples,
        Type,
        VerticalAngle
    };
    Kind kind;
    Vector3Function vector;  // Location .. Sky, FocalPoint
    // Angle: field of view in degrees (perspective and orthographic: the
    // horizontal one, setting direction's length; fisheye: the whole
    // circle's; spherical: the horizontal; panoramic: read, unused, as in
    // POV-Ray); VerticalAngle: a spherical camera's vertical field of view;
    // Aperture: the lens' aperture (scene units); BlurSamples: POV-Ray's
    // count (0 or less, or an aperture of 0: no focal blur).
    TimeFunction angle;
    TransformStep step;                         // Transform
    CameraType type = CameraType::Perspective;  // Type
    std::shared_ptr<const MeshCamera> mesh;     // Type Mesh: its meshes and rules
};

// The camera's vectors at one instant, as POV-Ray uses them to make rays:
// a ray through screen point (u, v) in [-0.5, 0.5]^2 has direction
// direction + u * right + v * up, from location.
struct CameraFrame {
    CameraType type = CameraType::Perspective;
    glm::dvec3 location{0, 0, 0};
    glm::dvec3 direction{0, 0, 1};
    glm::dvec3 right{1.33, 0, 0};
    glm::dvec3 up{0, 1, 0};
    glm::dvec3 sky{0, 1, 0};
    // Focal blur (POV-Ray's, tracer/focal_blur.hpp): the aperture (0: a
    // pinhole) and the distance from the location to the plane in focus,
    // |focal_point - location| before the camera's transforms, else the
    // direction's length (POV-Ray's Parse_Camera).
    double aperture = 0.0;
    double focal_distance = 1.0;
    // Fisheye, ultra_wide_angle, omnimax and the cylinders: the camera's
    // angle in degrees (POV-Ray's default 90).
    double angle = 90.0;
    // Spherical: the horizontal and vertical fields of view in degrees
    // (POV-Ray's defaults 360 and 180).
    double h_angle = 360.0, v_angle = 180.0;
    // A mesh camera's meshes (its rays leave their faces; the location's
    // and direction's z say how, MeshCamera::ray).
    std::shared_ptr<const MeshCamera> mesh;
};

struct CameraRecord {
    std::vector<CameraItem> items;
    // A camera chosen by branches on clock (language/time_branch.hpp): the
    // items of each piece of time, the first piece that holds t winning;
    // `items` where none does.
    struct Piece {
        Lifetime when;
        std::vector<CameraItem> items;
    };
    std::vector<Piece> pieces;
    // normal { } in the camera: each ray's direction perturbed by the
    // pattern at its point on the screen (x, y from -0.5 to 0.5, z 0), as
    // POV-Ray's TracePixel::CreateCameraRay does.
    std::optional<Normal> normal;

    bool depends_on_time() const;
    // The camera at time t. POV-Ray does not change `right` to match the
    // image's aspect ratio, and neither does hexant.
    CameraFrame evaluate(double t) const;

  private:
    static CameraFrame evaluate_items(const std::vector<CameraItem>& items, double t);
};

}  // namespace hexant::runtime
