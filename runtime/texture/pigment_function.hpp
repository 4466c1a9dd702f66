// POV-Ray's pigment function, `#declare F = function { pigment { P } }`:
// F(x, y, z) is P's colour at the point, a vector of five (red, green, blue,
// filter, transmit) read by component (`F(x, y, z).red`, `.x`, `.gray`),
// as POV-Ray's Parse_DeclareFunction makes a VECTFUNCT of return size 5.
// The point is in the pigment's space before its own transforms (they
// apply, as they do on a surface), with no surface there: slope reads no
// normal, uv_mapping reads (0, 0). A pigment has no bound over a box of
// points, so an isosurface cannot use it (bounded() is false).
#pragma once

#include <memory>
#include <string>

#include "runtime/texture/material.hpp"
#include "runtime/time/point_function.hpp"

namespace hexant::runtime {

class TextureEvaluator;

class PigmentFunction final : public PointFunction {
  public:
    // Throws ObjectError, naming the place, for a pattern hexant lacks.
    // `name` for messages: a pattern function is one too (its pigment a
    // grey ramp of the pattern).
    explicit PigmentFunction(const Pigment& pigment, std::string name = "pigment function");
    ~PigmentFunction() override;

    std::string name() const override { return name_; }
    int components() const override { return 5; }
    bool depends_on_time() const override { return depends_on_time_; }
    double at(int component, const glm::dvec3& p, double t) const override;

  private:
    std::unique_ptr<const TextureEvaluator> evaluator_;
    bool depends_on_time_ = false;
    std::string name_;
};

}  // namespace hexant::runtime
