// `hexant dump`: every record of a scene with its parameters evaluated at one
// clock value, one per line, in a stable format for tests and for comparing
// with POV-Ray (numbers printed with %.10g).
#pragma once

#include <ostream>

#include "runtime/scene/scene.hpp"

namespace hexant::app {

void dump_scene(const runtime::SceneDescription& scene, double clock, std::ostream& out);

}  // namespace hexant::app
