// POV-Ray 3.7's radiosity pretrace (backend/render/radiositytask.cpp and
// View::StartRender): before a frame is rendered, passes over the image at
// block sizes from pretrace_start to pretrace_end of its larger side,
// halving, one jittered ray per block, whose hits gather samples into the
// frame's irradiance cache; the render then reuses them.
//
// The order of the records does not depend on the threads: the image is
// cut into 32-pixel tiles (POV-Ray's render blocks), each traced by one
// thread in order, its records reused within the tile as they are made
// (POV-Ray reuses a pass's records only within their tile too) and added
// to the cache after the pass, tile by tile. POV-Ray's adaptive pretrace
// (nearest_count's second value) is not made: every tile takes every pass.
#pragma once

#include <functional>

#include "runtime/scene/radiosity_settings.hpp"
#include "tracer/radiosity_cache.hpp"
#include "tracer/thread_state.hpp"

namespace hexant::tracer {

// `trace(px, py, state)` traces the camera ray through image point (px, py)
// (pixels' corners at whole numbers); `state()` the calling thread's state.
void radiosity_pretrace(const runtime::RadiositySettings& settings, int width, int height,
                        RadiosityCache& cache,
                        const std::function<void(double, double, ThreadState&)>& trace,
                        const std::function<ThreadState&()>& state);

// The block sizes of the passes, in pixels, largest first (empty: none).
std::vector<double> pretrace_sizes(const runtime::RadiositySettings& settings, int width,
                                   int height);

}  // namespace hexant::tracer
