// height_field against POV-Ray 3.7 (tests/tracer/pov_reference_test.cpp,
// clock 0 and 0.5): bump.png (32 x 32 8-bit gray, make_bump.py) as a plain
// height field (flat triangles) and a smooth one whose water level rises
// with clock, a ball moving over them, on a checkered floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.2, -4.2> look_at <0, 0.2, 0> angle 55 }
light_source { <3, 6, -4> color rgb 1 }
light_source { <-4, 3, -3> color rgb 0.3 }
background { color rgb <0.1, 0.1, 0.3> }
plane { y, 0 pigment { checker color rgb 0.8 color rgb 0.4 scale 0.5 } }
height_field {
  png "bump.png"
  pigment { color rgb <0.9, 0.6, 0.3> }
  finish { phong 0.4 }
  translate <-0.5, 0, -0.5>
  scale <1.6, 0.9, 1.6>
  rotate y * 20
  translate <-1.1, 0, 0.2>
}
height_field {
  png "bump.png"
  smooth
  water_level 0.1 + 0.3 * clock
  pigment { color rgb <0.3, 0.8, 0.5> }
  finish { phong 0.6 }
  translate <-0.5, 0, -0.5>
  scale <1.6, 0.9, 1.6>
  rotate y * -30
  translate <1.1, 0, 0.2>
}
sphere { <-0.6 + 1.2 * clock, 1.2, -0.9>, 0.25 pigment { color rgb <0.9, 0.2, 0.2> } finish { phong 0.8 } }
box { <-0.2, 0, -1.6>, <0.2, 0.3, -1.2> pigment { color rgb <0.3, 0.4, 0.95> } }
