// A texture compiled for the tracer: the pigment's pattern, the finish and
// the interior, evaluated at a world point and time into plain numbers.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "runtime/compiled_function.hpp"
#include "runtime/material.hpp"
#include "runtime/material_sample.hpp"
#include "runtime/motion.hpp"

namespace hexant::runtime {

class TextureEvaluator {
public:
    // `texture.transform` maps texture space to the world (the object's
    // transforms written after the texture are already appended, so the
    // texture moves with the object). Throws ObjectError, naming the place,
    // for a pattern hexant does not have.
    TextureEvaluator(const Texture& texture, const std::optional<Interior>& interior);

    MaterialSample at(const glm::dvec3& world_point, double t) const;
    bool depends_on_time() const { return depends_on_time_; }

private:
    struct CompiledColour {
        std::array<CompiledScalar, 5> c;
    };
    static CompiledColour compile(const ColourFunction& colour);

    Pigment::Pattern pattern_;
    std::vector<CompiledColour> colours_;
    Motion pattern_to_world_;  // the pigment's transform, then the texture's
    CompiledScalar ambient_, diffuse_, brilliance_, phong_, phong_size_, specular_, roughness_,
        emission_, ior_;
    std::array<CompiledScalar, 3> reflection_;
    bool depends_on_time_ = false;
};

// POV-Ray's checker: which of the two colours a pattern point takes, by the
// parity of floor(x) + floor(y) + floor(z). POV-Ray 3.7's renders show no
// offset of the square edges (a 1e-3 offset, as older sources have, flips
// the pixels whose hits lie within 1e-3 of an edge; see
// tests/tracer/pov_reference).
int checker_index(const glm::dvec3& pattern_point);

}  // namespace hexant::runtime
