// POV-Ray's box { CORNER1, CORNER2 }: the object kind (runtime/objects/shape_kind.hpp).
#pragma once

#include <array>
#include <string_view>
#include <utility>
#include <vector>

#include "runtime/objects/flat_face.hpp"
#include "runtime/objects/shape_kind.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime {

namespace objects {
class BoxModel;
}  // namespace objects

struct Box {
    static constexpr std::string_view keyword = "box";
    using Model = objects::BoxModel;
    // Its solid is exactly what lies behind all its flat faces (the
    // coincident-faces check cuts a CSG's other members by it).
    static constexpr bool kConvexPolyhedron = true;

    Vector3Function corner1, corner2;

    static Box read(const objects::ShapeArguments& a) {
        a.no_options();
        a.need(2, 2, "two corners");
        return {a.vector3(0, "box's first corner"), a.vector3(1, "box's second corner")};
    }
    template <class F>
    void parameters(F&& f) const {
        f("corner1", "first corner", corner1);
        f("corner2", "second corner", corner2);
    }
    // Its six faces, each facing out along its axis.
    std::vector<objects::FlatFace> flat_faces(double t) const {
        const glm::dvec3 lo = glm::min(corner1(t), corner2(t));
        const glm::dvec3 hi = glm::max(corner1(t), corner2(t));
        std::vector<objects::FlatFace> faces;
        for (int a = 0; a < 3; ++a) {
            const int b = (a + 1) % 3, c = (a + 2) % 3;
            for (const double side : {-1.0, 1.0}) {
                objects::FlatFace face;
                face.normal = glm::dvec3(0.0);
                face.normal[a] = side;
                face.point = side < 0.0 ? lo : hi;
                for (const auto& [u, v] : {std::pair{lo[b], lo[c]}, std::pair{hi[b], lo[c]},
                                           std::pair{hi[b], hi[c]}, std::pair{lo[b], hi[c]}}) {
                    glm::dvec3 corner = face.point;
                    corner[b] = u;
                    corner[c] = v;
                    face.corners.push_back(corner);
                }
                faces.push_back(std::move(face));
            }
        }
        return faces;
    }
};

}  // namespace hexant::runtime

#include "runtime/objects/box/box_model.hpp"
