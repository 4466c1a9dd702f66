// POV-Ray's sphere { CENTER, RADIUS }: the object kind (runtime/objects/shape_kind.hpp).
#pragma once

#include <array>
#include <string_view>

#include "runtime/objects/shape_kind.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime {

namespace objects {
class SphereModel;
}  // namespace objects

struct Sphere {
    static constexpr std::string_view keyword = "sphere";
    using Model = objects::SphereModel;

    Vector3Function center;
    TimeFunction radius;

    static Sphere read(const objects::ShapeArguments& a) {
        a.no_options();
        a.need(2, 2, "a centre and a radius");
        return {a.vector3(0, "sphere's centre"), a.number(1, "sphere's radius")};
    }
    template <class F>
    void parameters(F&& f) const {
        f("center", "centre", center);
        f("radius", "radius", radius);
    }
};

}  // namespace hexant::runtime

#include "runtime/objects/sphere/sphere_model.hpp"
