// POV-Ray's box { CORNER1, CORNER2 }: the object kind (runtime/objects/shape_kind.hpp).
#pragma once

#include <array>
#include <string_view>

#include "runtime/objects/shape_kind.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime {

namespace objects {
class BoxModel;
}  // namespace objects

struct Box {
    static constexpr std::string_view keyword = "box";
    using Model = objects::BoxModel;

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
};

}  // namespace hexant::runtime

#include "runtime/objects/box/box_model.hpp"
