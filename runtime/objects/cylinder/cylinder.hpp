// POV-Ray's cylinder { BASE, CAP, RADIUS [open] }: the object kind
// (runtime/objects/shape_kind.hpp).
#pragma once

#include <array>
#include <string_view>
#include <vector>

#include "runtime/objects/flat_face.hpp"
#include "runtime/objects/shape_kind.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime {

namespace objects {
class CylinderModel;
}  // namespace objects

struct Cylinder {
    static constexpr std::string_view keyword = "cylinder";
    static constexpr std::array<std::string_view, 1> settings{"open"};
    using Model = objects::CylinderModel;

    Vector3Function base, cap;
    TimeFunction radius;
    bool open = false;

    static Cylinder read(const objects::ShapeArguments& a) {
        a.no_options();
        a.need(3, 3, "two end points and a radius");
        return {a.vector3(0, "cylinder's base point"), a.vector3(1, "cylinder's cap point"),
                a.number(2, "cylinder's radius")};
    }
    void set(std::string_view, const objects::ShapeArguments& value) {
        open = objects::flag(value);
    }
    template <class F>
    void parameters(F&& f) const {
        f("base", "base point", base);
        f("cap", "cap point", cap);
        f("radius", "radius", radius);
        f("open", "open", open);
    }
    // Its two end caps, facing out along the axis (none when open).
    std::vector<objects::FlatFace> flat_faces(double t) const {
        std::vector<objects::FlatFace> faces;
        if (open) return faces;
        const glm::dvec3 b = base(t), c = cap(t);
        objects::add_circle_face(faces, b, b - c, radius(t), false);
        objects::add_circle_face(faces, c, c - b, radius(t), false);
        return faces;
    }
};

}  // namespace hexant::runtime

#include "runtime/objects/cylinder/cylinder_model.hpp"
