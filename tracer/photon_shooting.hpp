// Shooting a frame's photons (POV-Ray 3.7's PhotonStrategyTask,
// PhotonEstimationTask and PhotonShootingTask, source/backend/lighting/):
// from each light that casts shadows at each photon target, over the
// target's bounding sphere on a grid of rings (theta) and steps around
// them (phi) whose spacing is photons' spacing times the target's factor
// at the target, jittered; each ring after one that met the target stops
// the target's shooting once a ring misses it past `autostop` of its
// angular radius.
//
// hexant shoots each photon at a time of its own across the frame's
// shutter, so a moving glass's caustic blurs as the glass does; the
// target's sphere holds it over the whole shutter. Random numbers are
// hashes of (light, target, ring, step), so a frame's photons are the same
// whatever the threads.
#pragma once

#include <functional>
#include <vector>

#include "runtime/objects/intelligent_object.hpp"
#include "tracer/photon_map.hpp"
#include "tracer/shader.hpp"
#include "tracer/thread_state.hpp"

namespace hexant::tracer {

// A frame's photons: those left on surfaces, and those left in media.
struct PhotonMaps {
    PhotonMap surface, media;
};

// The photons of one frame. `objects`: the scene's intelligent objects (the
// targets among them are grouped by ObjectFlags::photon_group); `time_at`
// maps a fraction of the shutter in [0, 1] to clock time; `state()` the
// calling thread's state. Counts the shooting in `counters`.
PhotonMaps shoot_photons(const Shader& shader,
                         const std::vector<runtime::IntelligentObjectPtr>& objects,
                         const std::function<double(double)>& time_at,
                         const std::function<ThreadState&()>& state, Counters& counters);

}  // namespace hexant::tracer
