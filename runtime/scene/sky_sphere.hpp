// POV-Ray's sky_sphere: pigments on a sphere at infinity, seen by every ray
// that hits nothing, layered over the background (POV-Ray 3.7's
// Trace::ComputeSky, for scenes of version 3.7: each layer, the last first,
// adds its colour times its opacity and what the layers above let through;
// the background comes last). A pigment is evaluated at the ray's
// direction taken through the sky's transform, at the ray's time.
#pragma once

#include <vector>

#include "runtime/motion/transform.hpp"
#include "runtime/texture/material.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime {

struct SkySphere {
    std::vector<Pigment> pigments;  // in the order written; the last is on top
    Transform transform;
    ColourFunction emission{{1.0, 1.0, 1.0, 0.0, 0.0}};
};

}  // namespace hexant::runtime
