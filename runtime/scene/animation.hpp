// The animation's frames and their clock values, after POV-Ray's animation
// options (Initial_Frame, Final_Frame, Initial_Clock, Final_Clock,
// Cyclic_Animation) plus the shutter: frame k's shutter stays open for
// `shutter` of clock_delta, opening at its clock, centred on it or closing
// at it (shutter_position), its samples' times drawn by the shutter curve;
// with a rolling shutter, each row of the image opens later than the one
// above. A non-cyclic animation's first and last shutters are cut to
// [Initial_Clock, Final_Clock], where the scene is defined.
#pragma once

#include "runtime/scene/shutter_curve.hpp"

namespace hexant::runtime {

// Where a frame's exposure sits against the frame's clock (POV-Ray's
// instant for the frame): opening at it, centred on it, or closing at it,
// as Cycles' motion blur position and MegaPOV's and pbrt's shutter open
// and close times place it.
enum class ShutterPosition { Start, Centre, End };

struct Animation {
    int width = 320;
    int height = 240;
    int initial_frame = 1;
    int final_frame = 1;
    double initial_clock = 0.0;
    double final_clock = 1.0;
    bool cyclic = false;
    // Whether a still's clock was given (POV-Ray's +K, hexant's --clock C):
    // POV-Ray's clock_on is 1 then, as in an animation (its Parser's
    // useClock: whether the Clock option exists).
    bool clock_given = false;
    double shutter = 1.0;
    // How the shutter opens and closes over its open interval (a box: fully
    // open throughout).
    ShutterCurve shutter_curve;
    // A rolling shutter (as a CMOS sensor's readout): the time, as a
    // fraction of clock_delta, from the top row's opening to the bottom
    // row's. A sample at height y (0 at the top edge, 1 at the bottom) opens
    // at the frame's clock plus y rolling_shutter clock_delta. 0: a global
    // shutter, every row at once.
    double rolling_shutter = 0.0;
    // Where each frame's exposure (shutter and rolling readout) sits
    // against its clock (--shutter-position; README, "Motion blur").
    ShutterPosition shutter_position = ShutterPosition::Start;
    // Whether a non-cyclic animation may be sampled outside [Initial_Clock,
    // Final_Clock] (--shutter-beyond-range): otherwise the first and last
    // frames' exposures are cut to that range, where a scene's formulas
    // are meant to hold (a scale valid on [0, 1] shrinks through zero past
    // 1; `#if (clock < 1)` objects vanish). A cyclic animation is periodic
    // by its own declaration and is never cut.
    bool shutter_beyond_range = false;

    int frame_count() const { return final_frame - initial_frame + 1; }
    bool is_animation() const { return final_frame != initial_frame; }
    // Whether `clock` moves during the rendering: an animation, or one
    // cyclic frame whose shutter spans the cycle (clock_delta).
    bool clock_runs() const { return is_animation() || cyclic; }
    // The clock step between frames.
    double clock_delta() const;
    // The clock value of frame k (the shutter's opening).
    double clock_of_frame(int frame) const;
    // The fraction of a frame's exposure that falls before its clock: 0
    // (start), 1/2 (centre) or 1 (end).
    double shutter_lead() const;
    // The first instant that belongs to frame k (frame_number switches
    // there): its clock less shutter_lead() clock steps, halfway between
    // two frames' exposures when they are centred; frame k's samples fall
    // from it on (exposure() <= 1) and frame k-1's before it.
    double frame_start(int frame) const {
        return clock_of_frame(frame) - shutter_lead() * clock_delta();
    }
    // The clock interval frame k's samples span: from `open` for `length`
    // (signed as clock_delta: a clock running backwards has length <= 0).
    struct Window {
        double open, length;
        double close() const { return open + length; }
    };
    // Frame k's exposure placed by shutter_position and, in a non-cyclic
    // animation, cut to [Initial_Clock, Final_Clock] (unless
    // shutter_beyond_range). Empty (length 0) for a still.
    Window frame_window(int frame) const;
    // The first frame's opening and the last frame's closing.
    double time_begin() const { return frame_window(initial_frame).open; }
    double time_end() const { return frame_window(final_frame).close(); }
    // The fraction of clock_delta a frame's samples span: its rows' shutter
    // openings spread over rolling_shutter, each open for `shutter`.
    double exposure() const { return shutter + rolling_shutter; }
    // When frame k's samples fall: its opening, how long its shutter is
    // open and how long its rows take to open, in clock units, and the
    // curve. at(row, when): the time of a sample at `row` (0 top edge, 1
    // bottom) of the image and `when` (a uniform coordinate in [0, 1)) of
    // its shutter. (Summed in this order so that a box shutter without
    // rolling gives the very doubles it always gave: open + when
    // (shutter delta).) A window cut to the clock's range keeps the
    // shutter's and the readout's proportions, both shortened alike.
    struct FrameClock {
        double open, shutter_length, rolling_length;
        const ShutterCurve* curve;
        double at(double row, double when) const {
            return open + curve->warp(when) * shutter_length + row * rolling_length;
        }
    };
    FrameClock frame_clock(int frame) const;
    double sample_time(int frame, double row, double when) const {
        return frame_clock(frame).at(row, when);
    }
};

}  // namespace hexant::runtime
