// POV-Ray's plane { NORMAL, DISTANCE }: all points p with dot(p, normal) =
// distance; the solid is the side the normal points away from. The object
// kind (runtime/objects/shape_kind.hpp).
#pragma once

#include <array>
#include <string_view>
#include <vector>

#include "runtime/objects/flat_face.hpp"
#include "runtime/objects/shape_kind.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime {

namespace objects {
class PlaneModel;
}  // namespace objects

struct Plane {
    static constexpr std::string_view keyword = "plane";
    using Model = objects::PlaneModel;
    // Its solid is exactly what lies behind all its flat faces (the
    // coincident-faces check cuts a CSG's other members by it).
    static constexpr bool kConvexPolyhedron = true;

    Vector3Function normal;
    TimeFunction distance;

    static Plane read(const objects::ShapeArguments& a) {
        a.no_options();
        a.need(2, 2, "a normal and a distance");
        return {a.vector3(0, "plane's normal"), a.number(1, "plane's distance")};
    }
    template <class F>
    void parameters(F&& f) const {
        f("normal", "normal", normal);
        f("distance", "distance", distance);
    }
    // The whole plane (a zero normal: none, as the shape is empty).
    std::vector<objects::FlatFace> flat_faces(double t) const {
        const glm::dvec3 n = normal(t);
        const double length = glm::length(n);
        if (!(length > 0.0)) return {};
        return {objects::FlatFace{n, n / length * distance(t), {}, false}};
    }
};

}  // namespace hexant::runtime

#include "runtime/objects/plane/plane_model.hpp"
