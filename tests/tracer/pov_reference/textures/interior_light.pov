// Light inside objects: interior fade_distance, fade_power (a power and
// the exponential from 1000 on) and fade_colour on what is seen through
// glass and on the shadows it casts, the distance moving with clock; faked
// caustics on a sphere and on a bumpy plane given its normal after a
// translate (POV-Ray does not move a normal written after the object's
// transforms). tests/tracer/pov_reference_test.cpp compares hexant's
// stills with POV-Ray 3.7's (README.md, "Textures").
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 3, -6> look_at <0, 0.3, 0> angle 60 }
light_source { <2, 12, -3>, rgb 1 }
plane { y, -0.6 pigment { checker rgb <0.2, 0.3, 0.6> rgb 0.9 } finish { ambient 0.2 } }
sphere { <-1.6, 0.3, 0>, 0.8 pigment { rgbf <1, 1, 1, 0.97> } finish { phong 0.5 }
  interior { ior 1.3 fade_distance 0.4 + 0.6 * clock fade_power 2 fade_colour rgb <1, 0.3, 0.2> } }
sphere { <0.2, 0.3, 0>, 0.8 pigment { rgbt <1, 1, 1, 0.95> }
  interior { ior 1.1 fade_distance 0.7 fade_power 1001 fade_color rgb <0.2, 0.8, 0.3> } }
sphere { <1.9, 0.3, 0.3>, 0.7 pigment { rgbf <0.8, 0.9, 1, 0.9> } interior { ior 1.4 caustics 0.8 } }
plane { y, 3 hollow pigment { rgbf <0.8, 0.8, 1, 0.92> } interior { caustics 1 }
  translate <3, 0, -2> normal { bumps 0.6 scale 0.5 } }
