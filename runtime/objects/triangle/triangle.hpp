// POV-Ray's triangle { P1, P2, P3 }: the object kind (runtime/objects/shape_kind.hpp).
#pragma once

#include <array>
#include <string_view>

#include "runtime/objects/shape_kind.hpp"
#include "runtime/vector_function.hpp"

namespace hexant::runtime {

namespace objects {
class TriangleModel;
}  // namespace objects

struct Triangle {
    static constexpr std::string_view keyword = "triangle";
    using Model = objects::TriangleModel;

    std::array<Vector3Function, 3> points;

    static Triangle read(const objects::ShapeArguments& a) {
        a.no_options();
        a.need(3, 3, "three corners");
        return {{a.vector3(0, "triangle's first corner"), a.vector3(1, "triangle's second corner"),
                 a.vector3(2, "triangle's third corner")}};
    }
    template <class F>
    void parameters(F&& f) const {
        f("p1", "first corner", points[0]);
        f("p2", "second corner", points[1]);
        f("p3", "third corner", points[2]);
    }
};

}  // namespace hexant::runtime

#include "runtime/objects/triangle/triangle_model.hpp"
