// superellipsoid against POV-Ray 3.7 (tests/tracer/pov_reference_test.cpp,
// clock 0 and 0.5): a row of shapes from a rounded box to a star
// (e, n = 0.2 .. 2.5), one whose exponents move with clock, one turned and
// scaled, one moving through the frame, over a checkered floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 0.8, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
light_source { <5, 3, -3> color rgb 0.3 }
background { color rgb <0.15, 0.2, 0.35> }
plane { y, 0 pigment { checker color rgb 0.9, color rgb 0.35 scale 0.5 } }
#declare F = finish { phong 0.5 phong_size 30 }
superellipsoid { <0.2, 0.2> pigment { color rgb <1, 0.4, 0.3> } finish { F } scale 0.7 translate <-3, 0.7, 1.5> }
superellipsoid { <1, 0.3> pigment { color rgb <0.3, 0.9, 0.4> } finish { F } scale 0.7 translate <-1, 0.7, 1.5> }
superellipsoid { <2.5, 2.5> pigment { color rgb <0.3, 0.5, 1> } finish { F } scale 0.8 translate <1, 0.8, 1.5> }
superellipsoid { <0.1 + 1.8 * clock, 1.5 - clock> pigment { color rgb <1, 0.85, 0.3> } finish { F }
  scale 0.7 translate <3, 0.7, 1.5> }
superellipsoid { <0.5, 1> pigment { color rgb <0.8, 0.4, 1> } finish { F }
  scale <1, 0.4, 0.6> rotate <20, 30 + 40 * clock, 0> translate <-1.5, 0.8, -1.2> }
superellipsoid { <3, 0.05> pigment { color rgb <0.4, 1, 1> } finish { F }
  scale 0.5 translate <0.5 + clock, 0.5, -1.5> }
