// Fog (F = 0: constant, 1: ground, 2: both, the second with turbulence)
// over a checkered floor and three balls at different depths, its
// distance moving with clock. tests/tracer/pov_reference_test.cpp compares
// hexant's stills with POV-Ray 3.7's (README.md, "Fog").
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (F) #declare F = 0; #end
camera { location <0, 1.5, -5> look_at <0, 0.8, 0> angle 60 }
light_source { <-5, 8, -6>, rgb 1 }
background { rgb <0.2, 0.3, 0.6> }
plane { y, 0 pigment { checker rgb 1, rgb 0.3 } }
sphere { <-1.5, 0.6, 0>, 0.6 pigment { rgb <1, 0.3, 0.2> } }
sphere { <0.5, 0.6, 4>, 0.6 pigment { rgb <0.2, 1, 0.3> } }
sphere { <2.5, 0.6, 12>, 0.6 pigment { rgb <0.3, 0.4, 1> } }
#if (F = 0 | F = 2)
  fog { color rgbf <0.8, 0.85, 0.9, 0.2> distance 6 + 4 * clock }
#end
#if (F = 1 | F = 2)
  fog { fog_type 2 distance 3 + clock color rgbt <0.9, 0.8, 0.7, 0.1> fog_offset 0.3 fog_alt 0.4
        #if (F = 2) turbulence 0.6 octaves 4 turb_depth 0.4 #end rotate z * 5 }
#end
