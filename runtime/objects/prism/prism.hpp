// POV-Ray's prism { [linear_sweep | conic_sweep] [linear_spline |
// quadratic_spline | cubic_spline | bezier_spline] HEIGHT1, HEIGHT2, N,
// POINT ... [open] }: the outline in x-z swept along y. The object kind
// (runtime/objects/shape_kind.hpp); `sturm` is a modifier the language reads
// for every object (hexant's solver needs no choice).
#pragma once

#include <array>
#include <string_view>
#include <vector>

#include "runtime/objects/prism/prism_geometry.hpp"
#include "runtime/objects/shape_kind.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime {

namespace objects {
class PrismModel;
}  // namespace objects

struct Prism {
    static constexpr std::string_view keyword = "prism";
    static constexpr std::array<std::string_view, 6> options{"bezier_spline", "conic_sweep",
                                                             "cubic_spline",  "linear_spline",
                                                             "linear_sweep",  "quadratic_spline"};
    static constexpr std::array<std::string_view, 1> settings{"open"};
    using Model = objects::PrismModel;

    TimeFunction height1, height2;
    std::vector<Vector2Function> points;
    bool open = false;
    geometry::PrismSpline spline = geometry::PrismSpline::linear;
    geometry::PrismSweep sweep = geometry::PrismSweep::linear;

    static Prism read(const objects::ShapeArguments& a);
    void set(std::string_view, const objects::ShapeArguments& value) {
        open = objects::flag(value);
    }
    template <class F>
    void parameters(F&& f) const {
        f("height1", "first height", height1);
        f("height2", "second height", height2);
        f("points", "point", points);
        f("open", "open", open);
    }
};

}  // namespace hexant::runtime

#include "runtime/objects/prism/prism_model.hpp"
