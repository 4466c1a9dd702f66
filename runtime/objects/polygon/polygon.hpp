// POV-Ray's polygon { N, POINT ... }: one or more closed outlines in a
// common plane. The object kind (runtime/objects/shape_kind.hpp).
#pragma once

#include <array>
#include <string_view>
#include <vector>

#include "runtime/objects/shape_kind.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime {

namespace objects {
class PolygonModel;
}  // namespace objects

struct Polygon {
    static constexpr std::string_view keyword = "polygon";
    using Model = objects::PolygonModel;

    std::vector<Vector3Function> points;

    static Polygon read(const objects::ShapeArguments& a);
    template <class F>
    void parameters(F&& f) const {
        f("points", "point", points);
    }
};

}  // namespace hexant::runtime

#include "runtime/objects/polygon/polygon_model.hpp"
