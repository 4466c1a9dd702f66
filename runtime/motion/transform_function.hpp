// A transform as a function of a point (POV-Ray's `function { transform {
// T } }`, a VECTFUNCT of three components: F(x, y, z) is T applied to the
// point), for a transform that moves with clock: its matrix at the call's
// time. (A transform that does not move is written into the function's
// components as its affine map, language/actions/functions.hpp.)
#pragma once

#include <string>

#include <glm/mat4x4.hpp>

#include "runtime/motion/transform.hpp"
#include "runtime/time/point_function.hpp"

namespace hexant::runtime {

class TransformFunction final : public PointFunction {
  public:
    // `transform` affine (no deformation).
    explicit TransformFunction(Transform transform) : transform_(std::move(transform)) {}
    std::string name() const override { return "transform function"; }
    int components() const override { return 3; }
    bool depends_on_time() const override { return transform_.depends_on_time(); }
    double at(int component, const glm::dvec3& p, double t) const override {
        return (transform_.matrix_at(t) * glm::dvec4(p, 1.0))[component];
    }

  private:
    Transform transform_;
};

}  // namespace hexant::runtime
