// POV-Ray's isosurface { function { F } contained_by { box | sphere }
// threshold T accuracy A max_gradient G evaluate a, b, c open max_trace N
// all_intersections }: the solid where F(x, y, z) <= T inside its
// container (POV-Ray's IsoSurface::Inside), its surface F = T, closed by
// the container's walls where F < T unless `open`. The object kind
// (runtime/objects/shape_kind.hpp); its block has its own rule in the
// grammar (kOwnSyntax).
//
// F is a user function (runtime/time/user_function.hpp) and may read
// clock, as may T and the container: the surface moves through time. The
// search for hits does not need max_gradient where every part of F has an
// interval bound (isosurface_geometry.hpp bounds F by interval
// arithmetic); an F that calls a pigment function has none, and is
// searched as POV-Ray searches it, trusting max_gradient as F's Lipschitz
// bound along the ray. evaluate, max_trace and all_intersections are read
// and change nothing: they tune POV-Ray's own search.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "runtime/objects/shape_kind.hpp"
#include "runtime/time/time_tape.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime {

namespace objects {
class IsosurfaceModel;
}  // namespace objects

struct Isosurface {
    static constexpr std::string_view keyword = "isosurface";
    static constexpr bool kOwnSyntax = true;
    static constexpr std::array<std::string_view, 6> settings{
        "accuracy", "all_intersections", "max_gradient", "max_trace", "open", "threshold"};
    using Model = objects::IsosurfaceModel;

    // F's body: arguments 0, 1, 2 are x, y, z. Unset until `function` is read.
    std::optional<TimeFunction> function;
    TimeFunction threshold = 0.0;
    double accuracy = 0.001;  // POV-Ray's default, in the object's units
    // |grad F| at most this (POV-Ray's default 1.1): used only where F has
    // no interval bound.
    double max_gradient = 1.1;
    bool open = false;
    // contained_by: a box (POV-Ray's default, <-1, -1, -1> to <1, 1, 1>) or a sphere.
    bool sphere_container = false;
    Vector3Function corner1{{-1.0, -1.0, -1.0}}, corner2{{1.0, 1.0, 1.0}};
    Vector3Function center{{0.0, 0.0, 0.0}};
    TimeFunction radius = 1.0;

    void set(std::string_view setting, const objects::ShapeArguments& value);
    std::optional<std::string> standalone_error() const {
        if (!function) return "an isosurface needs its function { }";
        return std::nullopt;
    }
    template <class F>
    void parameters(F&& f) const {
        if (function) {
            // Its size, not its text: a body that calls functions is a
            // graph whose text can be exponentially longer than it.
            const TimeTape tape = TimeTape::compile({*function});
            f("function", "function",
              objects::DescribedParameter{"a user function of " + std::to_string(tape.size()) +
                                          " operations"});
        }
        f("threshold", "threshold", threshold);
        if (sphere_container) {
            f("center", "container's centre", center);
            f("radius", "container's radius", radius);
        } else {
            f("corner1", "container's first corner", corner1);
            f("corner2", "container's second corner", corner2);
        }
    }
};

}  // namespace hexant::runtime

#include "runtime/objects/isosurface/isosurface_model.hpp"
