// POV-Ray's smooth_triangle { P1, N1, P2, N2, P3, N3 }: a triangle whose
// shading normal blends the corners' normals. The object kind
// (runtime/objects/shape_kind.hpp).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "runtime/objects/shape_kind.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime {

namespace objects {
class SmoothTriangleModel;
}  // namespace objects

struct SmoothTriangle {
    static constexpr std::string_view keyword = "smooth_triangle";
    using Model = objects::SmoothTriangleModel;

    std::array<Vector3Function, 3> points;
    std::array<Vector3Function, 3> normals;
    std::optional<std::array<Vector2Function, 3>> uv_vectors;  // as Triangle's
    static constexpr std::array<std::string_view, 1> settings{"uv_vectors"};

    static SmoothTriangle read(const objects::ShapeArguments& a) {
        a.no_options();
        a.need(6, 6, "three corners, each with its normal");
        return {{a.vector3(0, "smooth_triangle's first corner"),
                 a.vector3(2, "smooth_triangle's second corner"),
                 a.vector3(4, "smooth_triangle's third corner")},
                {a.vector3(1, "smooth_triangle's first normal"),
                 a.vector3(3, "smooth_triangle's second normal"),
                 a.vector3(5, "smooth_triangle's third normal")},
                std::nullopt};
    }
    template <class F>
    void parameters(F&& f) const {
        f("p1", "first corner", points[0]);
        f("n1", "first normal", normals[0]);
        f("p2", "second corner", points[1]);
        f("n2", "second normal", normals[1]);
        f("p3", "third corner", points[2]);
        f("n3", "third normal", normals[2]);
    }
    void set(std::string_view, const objects::ShapeArguments& value) {
        uv_vectors = objects::read_uv_vectors(value);
    }
    std::optional<std::string> standalone_error() const {
        if (!uv_vectors) return std::nullopt;
        return std::string(
            "uv_vectors belong to a smooth_triangle in a mesh (POV-Ray 3.7 reads them only there)");
    }
};

}  // namespace hexant::runtime

#include "runtime/objects/triangle/triangle_model.hpp"
