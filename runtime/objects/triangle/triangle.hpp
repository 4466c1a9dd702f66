// POV-Ray's triangle { P1, P2, P3 }: the object kind (runtime/objects/shape_kind.hpp).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/objects/flat_face.hpp"
#include "runtime/objects/shape_kind.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime {

namespace objects {
class TriangleModel;
}  // namespace objects

struct Triangle {
    static constexpr std::string_view keyword = "triangle";
    using Model = objects::TriangleModel;

    std::array<Vector3Function, 3> points;
    // uv_vectors <u1, v1>, <u2, v2>, <u3, v3>: the corners' texture
    // coordinates, which POV-Ray 3.7 reads only for a triangle in a mesh
    // (the mesh blends them for uv_mapping).
    std::optional<std::array<Vector2Function, 3>> uv_vectors;
    static constexpr std::array<std::string_view, 1> settings{"uv_vectors"};

    static Triangle read(const objects::ShapeArguments& a) {
        a.no_options();
        a.need(3, 3, "three corners");
        return {{a.vector3(0, "triangle's first corner"), a.vector3(1, "triangle's second corner"),
                 a.vector3(2, "triangle's third corner")},
                std::nullopt};
    }
    template <class F>
    void parameters(F&& f) const {
        f("p1", "first corner", points[0]);
        f("p2", "second corner", points[1]);
        f("p3", "third corner", points[2]);
    }
    void set(std::string_view, const objects::ShapeArguments& value) {
        uv_vectors = objects::read_uv_vectors(value);
    }
    // Itself, seen from both sides (a degenerate one: none).
    std::vector<objects::FlatFace> flat_faces(double t) const {
        const glm::dvec3 a = points[0](t), b = points[1](t), c = points[2](t);
        const glm::dvec3 n = glm::cross(b - a, c - a);
        if (!(glm::length(n) > 0.0)) return {};
        return {objects::FlatFace{n, a, {a, b, c}, true}};
    }
    std::optional<std::string> standalone_error() const {
        if (!uv_vectors) return std::nullopt;
        return std::string(
            "uv_vectors belong to a triangle in a mesh (POV-Ray 3.7 reads them only there)");
    }
};

}  // namespace hexant::runtime

#include "runtime/objects/triangle/triangle_model.hpp"
