// julia_fractal against POV-Ray 3.7 (tests/tracer/pov_reference_test.cpp,
// clock 0 and 0.5): a quaternion z^2 + c (fractal1.pov's first) turned
// with clock; a quaternion cube whose parameter moves with clock; a
// hypercomplex z^2 + c (fractal2.pov's first) whose slice distance moves
// with clock; fractal4.pov's hypercomplex one, its parameter moving with
// clock; over a checkered floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 0.9, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
light_source { <5, 3, -3> color rgb 0.3 }
background { color rgb <0.15, 0.2, 0.35> }
plane { y, -0.5 pigment { checker color rgb 0.9, color rgb 0.35 scale 0.5 } }
#declare F = finish { phong 0.5 phong_size 30 }
julia_fractal { <-0.083, 0.0, -0.83, -0.025> quaternion sqr max_iteration 8 precision 15
  pigment { color rgb <1, 0.5, 0.25> } finish { F } rotate y * 90 * clock translate <-1.6, 1.8, 0.5> }
julia_fractal { <-0.03, 0.5 - 0.3 * clock, -0.2, -0.5> quaternion cube max_iteration 8 precision 15
  pigment { color rgb <0.3, 0.9, 0.4> } finish { F } scale 1.2 translate <1.6, 1.8, 0.5> }
julia_fractal { <0.2, 0.1, 0.59, -0.2> hypercomplex sqr max_iteration 7 precision 20
  slice <0, 0, 0, 1>, 0.2 * clock
  pigment { color rgb <0.8, 0.65, 0.85> } finish { F } rotate <83, 0, -70> translate <-1.3, 0.6, -1> }
julia_fractal { <-0.745, 0, 0.113 + 0.1 * clock, 0.05> hypercomplex max_iteration 9 precision 20
  pigment { color rgb <1, 0.85, 0.3> } finish { F } scale <0.6, 1, 0.6> rotate <135, -30, 0> translate <1.5, 0.6, -1> }
