// isosurface against POV-Ray 3.7 (tests/tracer/pov_reference_test.cpp,
// clock 0 and 0.5): a wavy torus (internal f_torus) whose ripples move
// with clock; a blob of two spheres cut by its box, closed (the walls show
// where the function is below the threshold); the same open; one in a
// sphere container whose threshold grows with clock; a rounded box
// (internal f_rounded_box) turned with clock; over a checkered floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare f_torus = function { internal(70) }
#declare f_rounded_box = function { internal(60) }
camera { location <0, 3, -8> look_at <0, 0.8, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
light_source { <5, 3, -3> color rgb 0.3 }
background { color rgb <0.15, 0.2, 0.35> }
plane { y, 0 pigment { checker color rgb 0.9, color rgb 0.35 scale 0.5 } }
#declare F = finish { phong 0.5 phong_size 30 }
#declare Waves = function(a, b, c) { f_torus(a, b, c, 0.7, 0.25) + 0.05 * sin(8 * atan2(c, a) + 6 * clock) }
isosurface { function { Waves(x, y, z) } contained_by { box { <-1.1, -0.4, -1.1>, <1.1, 0.4, 1.1> } }
  max_gradient 3 pigment { color rgb <1, 0.5, 0.25> } finish { F } rotate x * -25 translate <-2.2, 1, 1.5> }
#declare Pair = function { 1 - exp(-4 * ((x - 0.35) * (x - 0.35) + y * y + z * z)) - exp(-4 * ((x + 0.35) * (x + 0.35) + y * y + z * z)) }
isosurface { function { Pair(x, y, z) } threshold 0.35 contained_by { box { <-1, -0.6, -0.35>, <1, 0.6, 0.6> } }
  max_gradient 4 pigment { color rgb <0.3, 0.9, 0.4> } finish { F } translate <0.4, 0.8, 1.5> }
isosurface { function { Pair(x, y, z) } threshold 0.35 contained_by { box { <-1, -0.6, -0.35>, <1, 0.6, 0.6> } } open
  max_gradient 4 pigment { color rgb <0.3, 0.5, 1> } finish { F } rotate y * 30 translate <2.6, 0.8, 1.5> }
isosurface { function { x * x + y * y + z * z } threshold 0.3 + 0.4 * clock contained_by { sphere { <0, 0, 0.1>, 0.7 } }
  max_gradient 2 pigment { color rgb <1, 0.85, 0.3> } finish { F } translate <-1.3, 0.8, -1.4> }
isosurface { function { f_rounded_box(x, y, z, 0.15, 0.6, 0.3, 0.4) } contained_by { box { -0.7, 0.7 } }
  pigment { color rgb <0.8, 0.4, 1> } finish { F } rotate <20, 30 + 40 * clock, 0> translate <1, 0.6, -1.3> }
