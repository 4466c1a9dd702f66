// Vectors whose components are time functions: a sphere's moving centre, a
// colour that fades. Constant vectors cost no more than their numbers.
#pragma once

#include <array>

#include <glm/vec3.hpp>

#include "runtime/motion/spline.hpp"
#include "runtime/time/time_function.hpp"

namespace hexant::runtime {

struct Vector3Function {
    std::array<TimeFunction, 3> c;

    glm::dvec3 operator()(double t) const { return {c[0](t), c[1](t), c[2](t)}; }
    bool depends_on_time() const {
        return c[0].depends_on_time() || c[1].depends_on_time() || c[2].depends_on_time();
    }
};

struct Vector2Function {
    std::array<TimeFunction, 2> c;
    bool depends_on_time() const { return c[0].depends_on_time() || c[1].depends_on_time(); }
};

// A colour as POV-Ray holds it: red, green, blue, filter, transmit.
struct ColourFunction {
    std::array<TimeFunction, 5> c;

    Vector5 operator()(double t) const { return {c[0](t), c[1](t), c[2](t), c[3](t), c[4](t)}; }
    bool depends_on_time() const {
        for (const auto& f : c)
            if (f.depends_on_time()) return true;
        return false;
    }
};

}  // namespace hexant::runtime
