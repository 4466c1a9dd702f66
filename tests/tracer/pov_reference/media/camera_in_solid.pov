// camera_in_solid: the camera inside a clear ball that is not hollow, in
// fog: POV-Ray fogs a ray only where every interior around it is hollow
// (IsHollowRay), and a camera ray starts in the ball (its
// InitRayContainerState), so what lies inside the ball is seen without
// fog and what lies beyond it is fogged from the ball's surface on. The
// near sphere moves with clock. tests/tracer/pov_reference_test.cpp
// compares hexant's stills with POV-Ray 3.7's.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -4> look_at <0, 0.5, 0> angle 60 }
light_source { <-5, 10, -8>, rgb 1 }
fog { distance 3 color rgb <0.7, 0.75, 0.8> }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.2 } hollow }
sphere { <-0.8 + clock, 0.5, -2>, 0.5 pigment { rgb <0.9, 0.3, 0.2> } hollow }
sphere { <1.5, 1, 4>, 1 pigment { rgb <0.2, 0.5, 0.9> } hollow }
sphere { <0, 1, -4>, 3 pigment { rgbf 1 } finish { ambient 0 diffuse 0 } }
