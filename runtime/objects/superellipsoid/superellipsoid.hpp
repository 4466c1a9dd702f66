// POV-Ray's superellipsoid { <e, n> }: the solid
//   (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) <= 1
// inside the unit box. The object kind (runtime/objects/shape_kind.hpp);
// e (east-west) and n (north-south) may be time functions.
#pragma once

#include <string_view>

#include "runtime/objects/shape_kind.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime {

namespace objects {
class SuperellipsoidModel;
}  // namespace objects

struct Superellipsoid {
    static constexpr std::string_view keyword = "superellipsoid";
    using Model = objects::SuperellipsoidModel;

    TimeFunction e, n;

    static Superellipsoid read(const objects::ShapeArguments& a);
    template <class F>
    void parameters(F&& f) const {
        f("e", "east-west exponent", e);
        f("n", "north-south exponent", n);
    }
};

}  // namespace hexant::runtime

#include "runtime/objects/superellipsoid/superellipsoid_model.hpp"
