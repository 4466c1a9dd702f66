// lathe (linear, quadratic, cubic and bezier splines) and sor (closed and
// open) against POV-Ray 3.7 (tests/tracer/pov_reference_test.cpp, clock 0
// and 0.5): four vases in a back row, one per spline type, the cubic one's
// waist and the Bezier one's handle point moving with clock; in front a
// closed sor whose neck widens with clock and an open sor (a tube you see
// into) turned a little, under one point light over a checkered floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.6, -7> look_at <0, 0.9, 0> angle 55 }
light_source { <-4, 7, -6> color rgb 1 }
light_source { <5, 3, -3> color rgb 0.3 }
background { color rgb <0.15, 0.2, 0.35> }
plane { y, 0 pigment { checker color rgb 0.9, color rgb 0.35 scale 0.5 } }
#declare F = finish { phong 0.6 phong_size 30 }
lathe {
  linear_spline 6, <0, 0>, <0.6, 0>, <0.8, 0.6>, <0.35, 1.1>, <0.5, 1.6>, <0, 1.6>
  pigment { color rgb <1, 0.4, 0.3> } finish { F }
  translate <-3, 0, 1.5>
}
lathe {
  quadratic_spline 7, <0, -0.5>, <0, 0>, <0.7, 0.1>, <0.8, 0.8>, <0.5, 1.2>, <0.3, 1.7>, <0, 1.9>
  pigment { color rgb <0.3, 0.9, 0.4> } finish { F }
  translate <-1, 0, 1.5>
}
lathe {
  cubic_spline 8, <0, -0.5>, <0, 0>, <0.7, 0.05>, <0.8, 0.7>, <0.25 + 0.3 * clock, 1.2>, <0.55, 1.7>,
    <0, 1.8>, <0, 2.5>
  pigment { color rgb <0.3, 0.5, 1> } finish { F }
  translate <1, 0, 1.5>
}
lathe {
  bezier_spline 8,
    <0, 0>, <0.6, 0>, <1.0, 0.5>, <0.6, 0.9>,
    <0.6, 0.9>, <0.2 + 0.6 * clock, 1.3>, <0.7, 1.6>, <0, 1.7>
  pigment { color rgb <1, 0.85, 0.3> } finish { F }
  translate <3, 0, 1.5>
}
sor {
  7, <0.3, -0.4>, <0.6, 0>, <0.75, 0.4>, <0.3 + 0.2 * clock, 0.9>, <0.35, 1.3>, <0.6, 1.6>, <0.7, 2>
  pigment { color rgb <0.9, 0.5, 1> } finish { F }
  translate <-1.3, 0, -1>
}
sor {
  6, <0.5, -0.3>, <0.5, 0>, <0.7, 0.5>, <0.4, 1.0>, <0.55, 1.3>, <0.6, 1.6>
  open
  pigment { color rgb <0.4, 1, 0.9> } finish { F }
  rotate x * -25 translate <1.3, 0.3, -1>
}
