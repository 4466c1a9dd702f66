// sphere_sweep against POV-Ray 3.7 (tests/tracer/pov_reference_test.cpp,
// clock 0 and 0.5): a linear_spline sweep, a b_spline one whose middle
// sphere moves with clock and a cubic_spline one turning, over a floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.8, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
light_source { <5, 3, -3> color rgb 0.3 }
background { color rgb <0.15, 0.2, 0.35> }
plane { y, 0 pigment { checker color rgb 0.9, color rgb 0.35 scale 0.5 } }
#declare F = finish { phong 0.5 phong_size 30 }
sphere_sweep { linear_spline 3, <-1, 0, 0>, 0.3, <0, 1, 0>, 0.15, <1, 0.2, 0>, 0.4
  pigment { color rgb <1, 0.4, 0.3> } finish { F } translate <-2, 0.5, 1.5> }
sphere_sweep { b_spline 5, <-1.5, 0, 0>, 0.2, <-1, 0.5, 0>, 0.3, <0, 1 + clock, 0>, 0.35,
  <1, 0.3, 0>, 0.25, <1.5, 0.8, 0>, 0.2
  pigment { color rgb <0.3, 0.9, 0.4> } finish { F } translate <2, 0.3, 1.5> }
sphere_sweep { cubic_spline 5, <-1.5, 0, 0>, 0.2, <-1, 0.3, 0>, 0.25, <0, 0.8, 0.3>, 0.35,
  <1, 0.2, 0>, 0.25, <1.5, 0.5, 0>, 0.2
  pigment { color rgb <0.3, 0.5, 1> } finish { F } rotate y * (30 * clock) translate <0, 0.6, -1> }
