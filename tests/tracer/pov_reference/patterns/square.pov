// square: POV-Ray 3.7's block pattern of four colours on the unit squares of
// the x-z plane (its square_pattern; Parse_Pattern's blend list of 4), with
// the default colours, with colours of its own (one fading with clock),
// scaled, turned and moved with clock, under turbulence. The pattern's own
// file is runtime/texture/pattern/kinds/square.cpp;
// tests/tracer/pov_reference_test.cpp compares hexant's stills with POV-Ray
// 3.7's (README.md, "Patterns").
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -4> look_at <0, 0, 0.5> angle 60 }
plane { y, 0 pigment { square scale 0.5 rotate y * 20 * clock translate x * 0.3 * clock } finish { ambient 1 diffuse 0 } }
sphere { <1.2, 0.8, 0>, 0.7
  pigment { square rgb <1, 0.5, 0>, rgb <0, 0.2, 1>, rgb <1 - clock, 1, 0>, rgb 0.1 scale 0.25 rotate <30, 40, 0> }
  finish { ambient 1 diffuse 0 } }
sphere { <-1.2, 0.8, 0>, 0.7
  pigment { square color rgb 1, color rgb <0.8, 0, 0> scale 0.3 turbulence 0.3 } finish { ambient 1 diffuse 0 } }
box { <-0.4, 0.3, -1.6>, <0.4, 1.1, -0.8> pigment { square scale 0.2 translate <0, 0, 0.5 * clock> } finish { ambient 1 diffuse 0 } }
