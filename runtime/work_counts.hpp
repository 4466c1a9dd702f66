// Work the runtime does only for scenes that need it, counted per thread (a
// plain thread_local: nothing shared on hot paths). The tracer adds each
// thread's difference over a piece of work to its Counters, so that --stats
// shows, for instance, that a scene without deformations never maps a point
// through one.
#pragma once

#include <cstdint>

namespace hexant::runtime {

struct WorkCounts {
    std::uint64_t deformation_maps = 0;  // points or boxes through twist, taper, bend
};

inline thread_local WorkCounts this_thread_work;

}  // namespace hexant::runtime
