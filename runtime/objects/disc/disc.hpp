// POV-Ray's disc { CENTER, NORMAL, RADIUS [, HOLE_RADIUS] }: the object
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
class DiscModel;
}  // namespace objects

struct Disc {
    static constexpr std::string_view keyword = "disc";
    using Model = objects::DiscModel;

    Vector3Function center, normal;
    TimeFunction radius;
    TimeFunction hole_radius = 0.0;

    static Disc read(const objects::ShapeArguments& a) {
        a.no_options();
        a.need(3, 4, "a centre, a normal, a radius and optionally a hole radius");
        Disc disc{a.vector3(0, "disc's centre"), a.vector3(1, "disc's normal"),
                  a.number(2, "disc's radius")};
        if (a.size() == 4) disc.hole_radius = a.number(3, "disc's hole radius");
        return disc;
    }
    template <class F>
    void parameters(F&& f) const {
        f("center", "centre", center);
        f("normal", "normal", normal);
        f("radius", "radius", radius);
        f("hole_radius", "hole radius", hole_radius);
    }
    // Its outer circle (the hole left out of the check), seen from both sides.
    std::vector<objects::FlatFace> flat_faces(double t) const {
        std::vector<objects::FlatFace> faces;
        objects::add_circle_face(faces, center(t), normal(t), radius(t), true);
        return faces;
    }
};

}  // namespace hexant::runtime

#include "runtime/objects/disc/disc_model.hpp"
