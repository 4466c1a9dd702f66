#include "runtime/scene/animation.hpp"

namespace hexant::runtime {

double Animation::clock_delta() const {
    // A single frame is not an animation: POV-Ray's clock_delta is 0 there.
    // A cyclic one is the exception, as the cyclic rule (B - A) / N says
    // with N = 1: one frame whose shutter spans the whole cycle (a still
    // that blurs a full turn), which POV-Ray cannot express (its single
    // frame has no clock range).
    if (!is_animation() && !cyclic) return 0.0;
    const int steps = final_frame - initial_frame + (cyclic ? 1 : 0);
    if (steps <= 0) return 0.0;
    return (final_clock - initial_clock) / steps;
}

double Animation::clock_of_frame(int frame) const {
    if (!is_animation()) return initial_clock;  // (frame is initial_frame)
    return initial_clock + (frame - initial_frame) * clock_delta();
}

}  // namespace hexant::runtime
