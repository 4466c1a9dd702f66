// Animation clock rules checked against POV-Ray 3.7.0.10 (Debian's `povray`)
// with a scene that only #debugs the animation identifiers:
//   #debug concat("frame_number = ", str(frame_number,0,10), "\n")
//   #debug concat("clock = ", str(clock,0,10), "\n")
//   #debug concat("clock_delta = ", str(clock_delta,0,10), "\n")
//   (and likewise initial_clock, final_clock, initial_frame, final_frame,
//   clock_on)
// run as
//   povray +Iscene.pov +W1 +H1 -D -F +GDdebug.txt OPTIONS
// Recorded (frame: clock, clock_delta):
//   +KFI1 +KFF4 +KI0 +KF1      1: 0  2: 0.3333333433  3: 0.6666666865  4: 1
//                              clock_delta = 0.3333330000 in every frame
//   +KFI1 +KFF4 +KI0 +KF1 +KC  1: 0  2: 0.25  3: 0.5  4: 0.75
//                              clock_delta = 0.25; final_frame reads 5 (!)
//   +KFI0 +KFF2 +KI2 +KF-2     0: 2  1: 0  2: -2, clock_delta = -2
//   +KFI1 +KFF5 +KI0 +KF1 +SF3 +EF4   3: 0.5  4: 0.75, clock_delta = 0.25
//   (no options)               clock = 0, clock_delta = 0, clock_on = 0, and
//                              initial/final clock/frame and frame_number 0
//   +K0.25                     clock = 0.25, clock_delta = 0, clock_on = 1,
//                              initial/final clock/frame and frame_number 0
//   +KFI1 +KFF1 +KI0.5 +KF1    clock = 0 (not an animation: +K's clock, not
//                              Initial_Clock), clock_delta = 0, clock_on = 0
// POV-Ray carries the clock in single precision (0.3333333433) and
// clock_delta through a 6-digit string (0.333333); hexant keeps doubles, so
// the comparisons below allow 1e-6.
#include "runtime/scene/animation.hpp"

#include <catch2/catch.hpp>

using hexant::runtime::Animation;

namespace {

Animation make(int f0, int f1, double c0, double c1, bool cyclic) {
    Animation a;
    a.initial_frame = f0;
    a.final_frame = f1;
    a.initial_clock = c0;
    a.final_clock = c1;
    a.cyclic = cyclic;
    return a;
}

}  // namespace

TEST_CASE("non-cyclic animation: the last frame reaches final_clock", "[animation]") {
    const Animation a = make(1, 4, 0, 1, false);
    CHECK(a.clock_delta() == Approx(0.333333).margin(1e-6));
    CHECK(a.clock_of_frame(1) == Approx(0.0).margin(1e-6));
    CHECK(a.clock_of_frame(2) == Approx(0.3333333433).margin(1e-6));
    CHECK(a.clock_of_frame(3) == Approx(0.6666666865).margin(1e-6));
    CHECK(a.clock_of_frame(4) == Approx(1.0).margin(1e-6));
}

TEST_CASE("cyclic animation: final_clock is one step past the last frame", "[animation]") {
    const Animation a = make(1, 4, 0, 1, true);
    CHECK(a.clock_delta() == Approx(0.25).margin(1e-12));
    CHECK(a.clock_of_frame(1) == Approx(0.0).margin(1e-12));
    CHECK(a.clock_of_frame(2) == Approx(0.25).margin(1e-12));
    CHECK(a.clock_of_frame(3) == Approx(0.5).margin(1e-12));
    CHECK(a.clock_of_frame(4) == Approx(0.75).margin(1e-12));
    CHECK(a.time_end() == Approx(1.0).margin(1e-12));
}

TEST_CASE("the clock may run backwards", "[animation]") {
    const Animation a = make(0, 2, 2, -2, false);
    CHECK(a.clock_delta() == Approx(-2.0));
    CHECK(a.clock_of_frame(0) == Approx(2.0));
    CHECK(a.clock_of_frame(1) == Approx(0.0).margin(1e-12));
    CHECK(a.clock_of_frame(2) == Approx(-2.0));
}

TEST_CASE("rendering a subset of frames keeps the whole animation's clock", "[animation]") {
    const Animation a = make(1, 5, 0, 1, false);
    CHECK(a.clock_delta() == Approx(0.25));
    CHECK(a.clock_of_frame(3) == Approx(0.5));
    CHECK(a.clock_of_frame(4) == Approx(0.75));
}

TEST_CASE("a single frame has clock_delta 0", "[animation]") {
    const Animation single = make(1, 1, 0, 1, false);
    CHECK_FALSE(single.is_animation());
    CHECK(single.clock_delta() == 0.0);
    // Cyclic, one frame: the step is (B - A) / 1 (README, --cyclic), so the
    // frame's shutter spans the whole cycle from clock A.
    const Animation cycle = make(1, 1, 0, 1, true);
    CHECK(cycle.clock_delta() == 1.0);
    CHECK(cycle.clock_of_frame(1) == 0.0);
    CHECK(cycle.time_end() == Approx(cycle.shutter));
    // POV-Ray's single frame uses the +K clock; hexant keeps it in
    // initial_clock.
    const Animation at_quarter = make(1, 1, 0.25, 0.25, false);
    CHECK(at_quarter.clock_of_frame(1) == 0.25);
    CHECK(at_quarter.time_begin() == 0.25);
    CHECK(at_quarter.time_end() == 0.25);
}
