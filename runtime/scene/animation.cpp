#include "runtime/scene/animation.hpp"

#include <algorithm>

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

double Animation::shutter_lead() const {
    switch (shutter_position) {
        case ShutterPosition::Start:
            return 0.0;
        case ShutterPosition::Centre:
            return 0.5;
        case ShutterPosition::End:
            return 1.0;
    }
    return 0.0;
}

Animation::Window Animation::frame_window(int frame) const {
    const double length = exposure() * clock_delta();
    // (x - 0 * length is x: the start position gives the clock itself.)
    const double open = clock_of_frame(frame) - shutter_lead() * length;
    if (cyclic || !is_animation() || shutter_beyond_range || length == 0.0) return {open, length};
    const double lo = std::min(initial_clock, final_clock),
                 hi = std::max(initial_clock, final_clock);
    const double a = std::min(open, open + length), b = std::max(open, open + length);
    const double cut_a = std::clamp(a, lo, hi), cut_b = std::clamp(b, lo, hi);
    if (cut_a == a && cut_b == b) return {open, length};
    return length > 0.0 ? Window{cut_a, cut_b - cut_a} : Window{cut_b, cut_a - cut_b};
}

Animation::FrameClock Animation::frame_clock(int frame) const {
    const double delta = clock_delta();
    const Window window = frame_window(frame);
    const double full = exposure() * delta;
    // A cut window shortens the shutter and the readout alike; an uncut
    // one keeps the products the clock always gave.
    if (window.length == full)
        return {window.open, shutter * delta, rolling_shutter * delta, &shutter_curve};
    const double cut = window.length / full;
    return {window.open, shutter * delta * cut, rolling_shutter * delta * cut, &shutter_curve};
}

}  // namespace hexant::runtime
