// Fog inside hollow objects: the camera inside a hollow sky sphere (as
// POV-Ray's Basic_Scenes templates put it), a hollow glass sphere and a
// solid one side by side in ground fog whose distance moves with clock.
// POV-Ray fogs a ray only where every object it is inside is hollow.
// tests/tracer/pov_reference_test.cpp compares hexant's stills with
// POV-Ray 3.7's (README.md, "Fog").
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -6> look_at <0, 0.5, 0> angle 55 }
light_source { <-5, 8, -6>, rgb 1 }
fog { distance 4 + 4 * clock color rgb <0.7, 0.75, 0.8> }
sphere { 0, 1000 hollow pigment { gradient y color_map { [0 rgb <0.6, 0.7, 0.9>] [1 rgb <0.1, 0.2, 0.6>] } scale 1000 }
  finish { ambient 1 diffuse 0 } }
plane { y, -1 pigment { checker rgb 0.2 rgb 0.9 } }
sphere { <-1.3, 0.2, 1>, 1.1 hollow pigment { rgbf <1, 1, 1, 0.9> } interior { ior 1.0 } }
sphere { <1.3, 0.2, 1>, 1.1 pigment { rgbf <1, 1, 1, 0.9> } interior { ior 1.0 } }
