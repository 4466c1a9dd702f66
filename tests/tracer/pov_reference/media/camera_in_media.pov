// camera_in_media: the camera inside a hollow ball of emitting and
// absorbing media, looking at objects inside it and at the floor beyond
// it: every camera ray starts in the media (POV-Ray's
// InitRayContainerState), not only those that leave the ball before
// meeting anything. The box grows and the camera moves with clock. Made
// after the distribution's abyss.pov, whose camera swims in a media sphere.
// tests/tracer/pov_reference_test.cpp compares hexant's stills with
// POV-Ray 3.7's.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.5 * clock, 1, -4 + clock> look_at <0, 0.5, 0> angle 60 }
light_source { <-5, 10, -8>, rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.2 } }
box { <-1, 0, -1>, <1, 1.2 + clock, 1> pigment { rgb <0.9, 0.3, 0.2> } rotate y * 30 }
sphere { <1.8, 0.6, 1.5>, 0.6 pigment { rgb <0.2, 0.5, 0.9> } }
sphere { <0, 1, -2>, 8 pigment { rgbf 1 } finish { ambient 0 diffuse 0 } hollow
  interior { media { emission <0.02, 0.03, 0.06> absorption 0.08 } } }
