// A function of a point (x, y, z) and time that a time function calls
// without seeing into it (TimeOp::PointCall): a pigment's colour in a user
// function (`function { pigment { } }`, runtime/texture/pigment_function.hpp)
// and POV-Ray's noise (f_noise3d). Its components are numbered (a pigment's
// red, green, blue, filter, transmit); a call reads one.
//
// The point value is all every caller needs. Interval and derivative
// evaluators (isosurfaces, bounds of motions) need more: a kind that can
// bound itself over a box says so with bounded() and gives over() and
// gradient(); one that cannot (a pigment) gives the whole real line and no
// derivative, and the places that need bounds refuse it where it is written
// (language/actions/isosurfaces.hpp).
#pragma once

#include <array>
#include <limits>
#include <string>

#include <glm/vec3.hpp>

#include "runtime/time/interval.hpp"

namespace hexant::runtime {

class PointFunction {
  public:
    virtual ~PointFunction() = default;

    // For messages and dumps: "pigment function", "f_noise3d".
    virtual std::string name() const = 0;
    virtual int components() const = 0;
    virtual bool depends_on_time() const = 0;
    // Component `component` at point p and time t.
    virtual double at(int component, const glm::dvec3& p, double t) const = 0;

    // Whether over() and gradient() bound the function; when false, over()
    // is the whole real line and gradient() is NaN.
    virtual bool bounded() const { return false; }
    // A range holding the component over the box p and the times t.
    virtual Interval over([[maybe_unused]] int component,
                          [[maybe_unused]] const std::array<Interval, 3>& p,
                          [[maybe_unused]] const Interval& t) const {
        return Interval::entire();
    }
    // (d/dx, d/dy, d/dz, d/dt) of the component at p and t.
    virtual std::array<double, 4> gradient([[maybe_unused]] int component,
                                           [[maybe_unused]] const glm::dvec3& p,
                                           [[maybe_unused]] double t) const {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        return {nan, nan, nan, nan};
    }
};

}  // namespace hexant::runtime
