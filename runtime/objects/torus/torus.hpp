// POV-Ray's torus { MAJOR, MINOR }: in the x-z plane about the y axis. The
// object kind (runtime/objects/shape_kind.hpp).
#pragma once

#include <array>
#include <string_view>

#include "runtime/objects/shape_kind.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime {

namespace objects {
class TorusModel;
}  // namespace objects

struct Torus {
    static constexpr std::string_view keyword = "torus";
    using Model = objects::TorusModel;

    TimeFunction major_radius, minor_radius;

    static Torus read(const objects::ShapeArguments& a) {
        a.no_options();
        a.need(2, 2, "a major and a minor radius");
        return {a.number(0, "torus's major radius"), a.number(1, "torus's minor radius")};
    }
    template <class F>
    void parameters(F&& f) const {
        f("major_radius", "major radius", major_radius);
        f("minor_radius", "minor radius", minor_radius);
    }
};

}  // namespace hexant::runtime

#include "runtime/objects/torus/torus_model.hpp"
