// prism (every spline with linear_sweep and conic_sweep, open, sturm)
// against POV-Ray 3.7 (tests/tracer/pov_reference_test.cpp, clock 0 and
// 0.5): a back row swept straight (linear with a hole, quadratic, cubic with
// a point moving with clock, bezier whose height moves), a front row swept
// conically (linear, quadratic through its apex, cubic open and turned to
// show its inside, bezier with sturm whose heights move), under one point
// light over a checkered floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5.5, -6.5> look_at <0, 0.3, 0.6> angle 58 }
light_source { <-4, 7, -6> color rgb 1 }
light_source { <5, 3, -3> color rgb 0.3 }
background { color rgb <0.15, 0.2, 0.35> }
plane { y, 0 pigment { checker color rgb 0.9, color rgb 0.35 scale 0.5 } }
#declare F = finish { phong 0.6 phong_size 30 }
prism {
  linear_sweep linear_spline 0, 0.8 + 0.4 * clock, 10,
  <-0.7, -0.6>, <0.7, -0.6>, <0.8, 0.4>, <0, 0.8>, <-0.8, 0.4>, <-0.7, -0.6>,
  <-0.2, -0.2>, <0.2, -0.2>, <0, 0.3>, <-0.2, -0.2>
  pigment { color rgb <1, 0.4, 0.3> } finish { F }
  rotate y * 20 translate <-3, 0, 2.2>
}
prism {
  quadratic_spline linear_sweep 0, 1, 8,
  <-0.5, -0.8>, <0.5, -0.8>, <0.9, 0>, <0.5, 0.8>, <-0.5, 0.8>, <-0.9, 0>, <-0.5, -0.8>,
  <0.5, -0.8>
  pigment { color rgb <0.3, 0.9, 0.4> } finish { F }
  rotate y * 10 translate <-1, 0, 2.2>
}
prism {
  cubic_spline 0, 1.2, 9,
  <-0.5, -0.8>, <0.5, -0.8>, <0.9 + 0.4 * clock, 0>, <0.5, 0.8>, <-0.5, 0.8>, <-0.9, 0>,
  <-0.5, -0.8>, <0.5, -0.8>, <0.9, 0>
  pigment { color rgb <0.3, 0.5, 1> } finish { F }
  rotate y * -15 translate <1, 0, 2.2>
}
prism {
  bezier_spline linear_sweep 0, 0.6 + 0.6 * clock, 16,
  <-0.8, -0.8>, <-0.2, -1.1>, <0.2, -0.5>, <0.8, -0.8>,
  <0.8, -0.8>, <1.1, -0.2>, <0.5, 0.2>, <0.8, 0.8>,
  <0.8, 0.8>, <0.2, 1.1>, <-0.2, 0.5>, <-0.8, 0.8>,
  <-0.8, 0.8>, <-1.1, 0.2>, <-0.5, -0.2>, <-0.8, -0.8>
  pigment { color rgb <1, 0.85, 0.3> } finish { F }
  rotate y * 30 translate <3, 0, 2.2>
}
prism {
  conic_sweep linear_spline 0.3, 1, 6,
  <0.8, -0.7>, <0.8, 0.7>, <-0.8, 0.7>, <-0.2, 0>, <-0.8, -0.7>, <0.8, -0.7>
  pigment { color rgb <0.9, 0.5, 1> } finish { F }
  rotate x * 180 translate <-2.6, 1, -1> rotate y * 10
}
prism {
  quadratic_spline conic_sweep -0.6, 1, 8,
  <-0.5, -0.8>, <0.5, -0.8>, <0.9, 0>, <0.5, 0.8>, <-0.5, 0.8>, <-0.9, 0>, <-0.5, -0.8>,
  <0.5, -0.8>
  pigment { color rgb <0.4, 1, 0.9> } finish { F }
  scale 0.7 translate <-0.9, 0.45, -1>
}
prism {
  cubic_spline conic_sweep 0.2, 1, 9,
  <-0.5, -0.8>, <0.5, -0.8>, <0.9, 0>, <0.5, 0.8>, <-0.5, 0.8>, <-0.9, 0>,
  <-0.5, -0.8>, <0.5, -0.8>, <0.9, 0>
  open
  pigment { color rgb <1, 0.6, 0.2> } finish { F }
  scale 0.8 rotate x * -30 translate <0.9, 0.3, -1>
}
prism {
  bezier_spline conic_sweep 0.5 - 0.3 * clock, 1.1, 16,
  <-0.8, -0.8>, <-0.2, -1.1>, <0.2, -0.5>, <0.8, -0.8>,
  <0.8, -0.8>, <1.1, -0.2>, <0.5, 0.2>, <0.8, 0.8>,
  <0.8, 0.8>, <0.2, 1.1>, <-0.2, 0.5>, <-0.8, 0.8>,
  <-0.8, 0.8>, <-1.1, 0.2>, <-0.5, -0.2>, <-0.8, -0.8>
  sturm
  pigment { color rgb <0.8, 0.8, 0.8> } finish { F }
  scale 0.8 rotate y * 25 translate <2.7, 0, -1>
}
