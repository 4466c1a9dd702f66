// POV-Ray's lathe { [linear_spline | quadratic_spline | cubic_spline |
// bezier_spline] N, <P1>, ..., <PN> [sturm] }: a profile of <radius,
// height> points turned about the y axis. The object kind
// (runtime/objects/shape_kind.hpp); `sturm` is a modifier the language
// reads for every object (hexant's solver needs no choice).
#pragma once

#include <array>
#include <string_view>
#include <vector>

#include "runtime/objects/lathe/lathe_geometry.hpp"
#include "runtime/objects/shape_kind.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime {

namespace objects {
class LatheModel;
}  // namespace objects

struct Lathe {
    static constexpr std::string_view keyword = "lathe";
    static constexpr std::array<std::string_view, 4> options{"bezier_spline", "cubic_spline",
                                                             "linear_spline", "quadratic_spline"};
    using Model = objects::LatheModel;

    geometry::LatheSpline spline = geometry::LatheSpline::linear;
    std::vector<Vector2Function> points;

    static Lathe read(const objects::ShapeArguments& a);
    template <class F>
    void parameters(F&& f) const {
        f("points", "point", points);
    }
};

}  // namespace hexant::runtime

#include "runtime/objects/lathe/lathe_model.hpp"
