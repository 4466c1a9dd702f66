#include "runtime/animation.hpp"

namespace hexant::runtime {

double Animation::clock_delta() const {
    // A single frame is not an animation, cyclic or not: POV-Ray's
    // clock_delta is 0 there.
    if (!is_animation()) return 0.0;
    const int steps = final_frame - initial_frame + (cyclic ? 1 : 0);
    if (steps <= 0) return 0.0;
    return (final_clock - initial_clock) / steps;
}

double Animation::clock_of_frame(int frame) const {
    if (!is_animation()) return initial_clock;
    return initial_clock + (frame - initial_frame) * clock_delta();
}

}  // namespace hexant::runtime
