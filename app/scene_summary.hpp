// `hexant check`: a short summary of a scene that parsed: the camera, the
// lights, the objects and which of their parameters depend on time.
#pragma once

#include <ostream>

#include "runtime/scene/scene.hpp"

namespace hexant::app {

void summarize_scene(const runtime::SceneDescription& scene, std::ostream& out);

}  // namespace hexant::app
