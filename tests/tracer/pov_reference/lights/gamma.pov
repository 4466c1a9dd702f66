// parallel.pov with assumed_gamma 2.2 (the working space of older scenes:
// POV-Ray decodes it from each pixel before the file is encoded) and a
// background. A parallel light (its rays all along point_at - location, its shadows
// reaching back to the plane through it) turning with clock, beside a point
// light; balls casting shadows on a floor. tests/tracer/pov_reference_test.cpp
// compares hexant's stills with POV-Ray 3.7's (README.md, "Lights").
#version 3.7;
global_settings { assumed_gamma 2.2 }
background { rgb <0.3, 0.5, 0.7> }
camera { location <0, 3, -6> look_at <0, 0.5, 0> angle 60 }
light_source { <0, 6, 0>, rgb <1, 0.95, 0.9> parallel point_at <1 - 2 * clock, 0, 0.5> }
light_source { <-4, 3, -4>, rgb 0.3 }
plane { y, 0 pigment { checker rgb 1, rgb 0.5 } }
sphere { <-1.2, 0.5, 0>, 0.5 pigment { rgb <1, 0.3, 0.2> } finish { phong 0.5 } }
sphere { <1, 1, 1>, 0.4 pigment { rgb <0.2, 0.6, 1> } }
box { <-0.3, 0, -1.5>, <0.3, 1.2, -1.2> pigment { rgb <0.9, 0.8, 0.2> } }
sphere { <2, 7, 0>, 0.5 pigment { rgb 1 } }  // above the light's plane: casts no shadow
