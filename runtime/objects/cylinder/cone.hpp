// POV-Ray's cone { BASE, BASE_RADIUS, CAP, CAP_RADIUS [open] }: the object
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
class ConeModel;
}  // namespace objects

struct Cone {
    static constexpr std::string_view keyword = "cone";
    static constexpr std::array<std::string_view, 1> settings{"open"};
    using Model = objects::ConeModel;

    Vector3Function base;
    TimeFunction base_radius;
    Vector3Function cap;
    TimeFunction cap_radius;
    bool open = false;

    static Cone read(const objects::ShapeArguments& a) {
        a.no_options();
        a.need(4, 4, "a base point and radius and a cap point and radius");
        return {a.vector3(0, "cone's base point"), a.number(1, "cone's base radius"),
                a.vector3(2, "cone's cap point"), a.number(3, "cone's cap radius")};
    }
    void set(std::string_view, const objects::ShapeArguments& value) {
        open = objects::flag(value);
    }
    template <class F>
    void parameters(F&& f) const {
        f("base", "base point", base);
        f("base_radius", "base radius", base_radius);
        f("cap", "cap point", cap);
        f("cap_radius", "cap radius", cap_radius);
        f("open", "open", open);
    }
    // Its end caps of radius > 0, facing out along the axis (none when open).
    std::vector<objects::FlatFace> flat_faces(double t) const {
        std::vector<objects::FlatFace> faces;
        if (open) return faces;
        const glm::dvec3 b = base(t), c = cap(t);
        objects::add_circle_face(faces, b, b - c, base_radius(t), false);
        objects::add_circle_face(faces, c, c - b, cap_radius(t), false);
        return faces;
    }
};

}  // namespace hexant::runtime

#include "runtime/objects/cylinder/cylinder_model.hpp"
