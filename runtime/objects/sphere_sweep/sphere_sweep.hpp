// POV-Ray's sphere_sweep { linear_spline | b_spline | cubic_spline  N,
// <C1>, R1, ..., <CN>, RN  [tolerance T] }: the union of the spheres swept
// along a spline through (or, for b_spline, near) its modelling spheres
// (sphere_sweep_geometry.hpp). The object kind
// (runtime/objects/shape_kind.hpp). Centres and radii may be functions of
// time: a sweep that bends and swells with clock is one object.
#pragma once

#include <array>
#include <string_view>
#include <vector>

#include "runtime/objects/shape_kind.hpp"
#include "runtime/objects/sphere_sweep/sphere_sweep_geometry.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime {

namespace objects {
class SphereSweepModel;
}  // namespace objects

struct SphereSweep {
    static constexpr std::string_view keyword = "sphere_sweep";
    static constexpr std::array<std::string_view, 3> options{"b_spline", "cubic_spline",
                                                             "linear_spline"};
    static constexpr std::array<std::string_view, 1> settings{"tolerance"};
    using Model = objects::SphereSweepModel;

    geometry::SweepSpline spline = geometry::SweepSpline::linear;
    std::vector<Vector3Function> centres;
    std::vector<TimeFunction> radii;
    // POV-Ray's depth tolerance (hits nearer than it along the ray are
    // dropped; 1e-6 by default). Read and kept; hexant's hits do not use it
    // (sphere_sweep_geometry.hpp).
    TimeFunction tolerance = 1e-6;

    static SphereSweep read(const objects::ShapeArguments& a);
    void set(std::string_view setting, const objects::ShapeArguments& value);
    template <class F>
    void parameters(F&& f) const {
        f("centres", "a sphere_sweep sphere's centre", centres);
        f("radii", "a sphere_sweep sphere's radius", radii);
        f("tolerance", "sphere_sweep's tolerance", tolerance);
    }
};

}  // namespace hexant::runtime

#include "runtime/objects/sphere_sweep/sphere_sweep_model.hpp"
