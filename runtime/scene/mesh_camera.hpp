// POV-Ray 3.7's mesh_camera { RAYS DISTRIBUTION [MAX_DISTANCE] mesh { } ...
// [smooth] }: primary rays leave the faces of meshes instead of a lens
// (Parse_Mesh_Camera, parse.cpp; TracePixel::CreateCameraRay and
// operator(), tracepixel.cpp). A pixel's rays, one per ray number, are
// averaged over those made; a pixel with none is black.
//   distribution 0: ray n of pixel (x, y) leaves face y W + x of mesh n;
//   distribution 1: it leaves face y W + x + n F of the meshes' faces
//     summed (F of them in all);
//   distribution 2: the meshes side by side, mesh floor(x / (W / M)) for
//     column x, face y (W / M) + x of it (one ray);
//   distribution 3: the face of the first mesh whose uv triangle holds the
//     pixel's (u, v) = ((x - 0.5) / W, 1 - (y + 0.5) / H), from the point
//     there (one ray; `smooth`: its normal interpolated).
// A ray starts at the face's centre (distribution 3: its point), moved
// along the face's normal by the camera location's z, and runs along the
// normal (against it where the camera direction's z is below -1e-10); the
// mesh's transforms then apply, at the ray's time. The face normal is
// POV-Ray's, (P3 - P1) x (P2 - P1) normalized; a mesh { } drops its
// degenerate triangles as POV-Ray's does, a mesh2 keeps them.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "runtime/motion/transform.hpp"

namespace hexant::runtime {

namespace objects {
struct MeshData;
}  // namespace objects

class MeshCamera {
  public:
    // One mesh of the camera: its data, its faces as POV-Ray counts them
    // (indices into data->faces, in the order read), and its transforms.
    struct Mesh {
        std::shared_ptr<const objects::MeshData> data;
        std::vector<std::uint32_t> faces;
        Transform transform;
    };
    struct Ray {
        glm::dvec3 origin, direction;  // direction unit
    };

    // Checks POV-Ray's rules (std::invalid_argument naming the rule): at
    // least one ray per pixel, distribution 0 to 3, one ray for
    // distributions 2 and 3, smooth only with 3, no more rays than meshes
    // with 0, a max_distance of 0 or more.
    MeshCamera(unsigned rays_per_pixel, unsigned distribution, double max_distance, bool smooth,
               std::vector<Mesh> meshes);

    unsigned rays_per_pixel() const { return rays_per_pixel_; }
    unsigned distribution() const { return distribution_; }
    double max_distance() const { return max_distance_; }
    const std::vector<Mesh>& meshes() const { return meshes_; }

    // Ray `number` of the sample at (x, y) of a width by height image, in
    // POV-Ray's pixel coordinates (CreateCameraRay's after its half-pixel
    // moves: column x from 0 at the left edge, row y from 0 at the top),
    // at time t; `offset` is the camera location's z, `invert` whether its
    // direction's z is below -EPSILON. None where POV-Ray makes no ray.
    std::optional<Ray> ray(double x, double y, int width, int height, unsigned number,
                           double offset, bool invert, double t) const;

    // Calls add(p) with the corners of a box holding every ray's origin at
    // time t (the meshes' vertices moved by `offset` along any direction,
    // through their transforms).
    template <class Add>
    void origin_extent(double offset, double t, Add&& add) const {
        for (const auto& corner : origin_corners(offset, t)) add(corner);
    }

  private:
    std::vector<glm::dvec3> origin_corners(double offset, double t) const;
    std::optional<Ray> from_face(const Mesh& mesh, std::uint32_t face, double offset, bool invert,
                                 double t) const;
    std::optional<Ray> from_uv(double u, double v, double offset, bool invert, double t) const;
    // The ray from `point` on a face of `mesh` along its unit `normal`,
    // moved by `offset` along it, through the mesh's transforms at t.
    static std::optional<Ray> leave(const Mesh& mesh, const glm::dvec3& point,
                                    const glm::dvec3& normal, double offset, bool invert, double t);

    unsigned rays_per_pixel_, distribution_;
    double max_distance_;
    bool smooth_;
    std::vector<Mesh> meshes_;
    std::vector<std::size_t> summed_;  // faces of meshes 0..i (Mesh_Index)
    // Distribution 3: per tenth of u and of v, a bit per face of the first
    // mesh whose uv triangle reaches it (POV-Ray's U_Xref, V_Xref).
    std::array<std::vector<std::uint32_t>, 10> u_cells_, v_cells_;
};

}  // namespace hexant::runtime
