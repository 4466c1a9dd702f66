// POV-Ray's fog { }: a constant fog (fog_type 1) or a ground fog (2) whose
// density falls off above fog_offset over fog_alt along `up`; each fog
// mixes its colour into what a ray in the open sees, by exp(-depth /
// distance) (POV-Ray 3.7's Trace::ComputeFog, ComputeConstantFogColour,
// ComputeGroundFogColour). Every number may be a function of time.
#pragma once

#include <optional>

#include "runtime/motion/transform.hpp"
#include "runtime/texture/pattern/pattern.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime {

struct Fog {
    int type = 1;  // 1 constant, 2 ground
    TimeFunction distance = 0.0;
    ColourFunction colour{};  // rgb, filter, transmit
    TimeFunction alt = 0.0, offset = 0.0, turb_depth = 0.5;
    Vector3Function up{{0.0, 1.0, 0.0}};
    Transform up_transform;  // rotate and scale turn `up` (a translation does not move it)
    std::optional<pattern::Turbulence> turbulence;
};

}  // namespace hexant::runtime
