// A light dimmed and coloured by the fog on its way (media_attenuation on)
// beside one that is not, over a floor in ground fog and constant fog, the
// fog's distance moving with clock. tests/tracer/pov_reference_test.cpp
// compares hexant's stills with POV-Ray 3.7's (README.md, "Fog").
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -7> look_at <0, 0.3, 0> angle 55 }
light_source { <-6, 4, 2>, rgb <1, 0.9, 0.8> media_attenuation on }
light_source { <6, 3, -2>, rgb <0.4, 0.5, 0.7> }
fog { distance 5 + 5 * clock color rgbf <0.6, 0.6, 0.7, 0.2> }
fog { fog_type 2 distance 3 color rgb <0.8, 0.7, 0.6> fog_offset 0.2 fog_alt 0.6 }
plane { y, -0.5 pigment { checker rgb 0.2 rgb 0.9 } }
sphere { <-1, 0.4, 1>, 0.9 pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }
box { <0.6, -0.5, 0>, <2, 1, 1.4> pigment { rgb <0.3, 0.8, 0.4> } }
