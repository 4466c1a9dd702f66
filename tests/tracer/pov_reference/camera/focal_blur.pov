// Focal blur: the plane in focus moves from the near green ball (clock 0)
// to the middle one (clock 0.5) and the aperture opens with clock.
// blur_samples 400 with confidence and variance set so that POV-Ray takes
// them all. tests/tracer/pov_reference_test.cpp compares hexant's stills
// with POV-Ray 3.7's (README.md, "Camera").
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.5, 0> angle 50
         aperture 0.6 + 0.4 * clock blur_samples 400 focal_point <-1.6 + 3.2 * clock, 0.5, -2 + 4 * clock>
         confidence 0.999999 variance 0 }
light_source { <-3, 6, -5>, rgb 1 }
plane { y, 0 pigment { checker rgb 0.9, rgb 0.3 } }
sphere { <0, 0.5, 0>, 0.5 pigment { rgb <0.9, 0.4, 0.3> } }
sphere { <-1.6, 0.5, -2>, 0.5 pigment { rgb <0.3, 0.9, 0.4> } }
sphere { <1.8, 0.5, 3>, 0.5 pigment { rgb <0.3, 0.4, 0.9> } }
