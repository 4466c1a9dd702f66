// The animation's frames and their clock values, after POV-Ray's animation
// options (Initial_Frame, Final_Frame, Initial_Clock, Final_Clock,
// Cyclic_Animation) plus the shutter: frame k's shutter opens at its clock and
// stays open for `shutter` of clock_delta.
#pragma once

namespace hexant::runtime {

struct Animation {
    int width = 320;
    int height = 240;
    int initial_frame = 1;
    int final_frame = 1;
    double initial_clock = 0.0;
    double final_clock = 1.0;
    bool cyclic = false;
    double shutter = 1.0;

    int frame_count() const { return final_frame - initial_frame + 1; }
    bool is_animation() const { return final_frame != initial_frame; }
    // Whether `clock` moves during the rendering: an animation, or one
    // cyclic frame whose shutter spans the cycle (clock_delta).
    bool clock_runs() const { return is_animation() || cyclic; }
    // The clock step between frames.
    double clock_delta() const;
    // The clock value of frame k (the shutter's opening).
    double clock_of_frame(int frame) const;
    // The first frame's opening and the last frame's closing.
    double time_begin() const { return clock_of_frame(initial_frame); }
    double time_end() const { return clock_of_frame(final_frame) + shutter * clock_delta(); }
};

}  // namespace hexant::runtime
