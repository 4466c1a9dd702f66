// rainbow: POV-Ray's rainbow { } laid over what rays see (ComputeRainbow):
// a full bow over the sky and a ground of checks, fading with the distance
// a ray travels (distance 300: faint on the near ground, full on the sky);
// a second bow tilted by its up vector and cut to an arc with a falloff; a
// ball moving with clock in front of both. tests/tracer/pov_reference_test.cpp
// compares hexant's stills with POV-Ray 3.7's.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 20, -100> look_at <0, 25, 0> angle 80 }
light_source { <-300, 500, -400>, rgb 1 }
background { rgb <0.4, 0.6, 0.9> }
plane { y, 0 pigment { checker rgb <0.3, 0.6, 0.2> rgb <0.8, 0.8, 0.3> scale 20 } }
sphere { <-20 + 40 * clock, 25, -20>, 10 pigment { rgb <0.8, 0.2, 0.2> } }
rainbow {
  angle 42.5 width 8 distance 300 direction <-0.2, -0.2, 1>
  color_map {
    [0.0 rgbf <1, 0.5, 1, 1>] [0.2 rgbf <0.5, 0.5, 1, 0.8>] [0.4 rgbf <0.2, 1, 1, 0.8>]
    [0.6 rgbf <0.2, 1, 0.2, 0.8>] [0.8 rgbf <1, 1, 0.2, 0.8>] [1.0 rgbf <1, 0.2, 0.2, 1>] } }
rainbow {
  angle 30 width 6 distance 1e7 direction <0.1, -0.1, 1> up <0.3, 1, 0>
  arc_angle 150 falloff_angle 90
  color_map { [0 rgbt <1, 1, 1, 1>] [0.5 rgbt <1, 0.8, 0.4, 0.3>] [1 rgbt <1, 1, 1, 1>] } }
