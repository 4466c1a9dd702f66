// Soft shadows: a rectangular area light (5 by 5, its rows weighted as
// POV-Ray's full subdivision weighs them) and a circular one that orients
// to each lit point (4 by 4), both moving with clock. `adaptive 4`
// makes POV-Ray subdivide its grids fully. tests/tracer/pov_reference_test.cpp
// compares hexant's stills with POV-Ray 3.7's (README.md, "Lights").
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0.3, 0> angle 50 }
light_source { <-1 + clock, 5, -1>, rgb 1 area_light <2, 0, 0>, <0, 0, 2 - clock>, 5, 5 adaptive 4 }
light_source { <3, 4, -2>, rgb 0.4 area_light <1, 0, 0>, <0, 1, 0>, 4, 4 adaptive 4 circular orient rotate y * 40 * clock }
plane { y, 0 pigment { rgb 0.8 } }
sphere { <-0.5, 0.6, 0>, 0.6 pigment { rgb <0.9, 0.4, 0.3> } }
box { <0.6, 0, 0.2>, <1.3, 1.5, 0.9> pigment { rgb <0.3, 0.6, 0.9> } }
