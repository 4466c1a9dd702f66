// solid_in_media: a glass ball that is not hollow inside a hollow ball of
// glowing media blocks the media where the ray is in it (POV-Ray's
// IsHollowRay: media only where every interior around is hollow), and a
// hollow one beside it lets it through; the left ball moves with clock.
// Made after the distribution's hollow2.pov, which a shortcut broke once.
// tests/tracer/pov_reference_test.cpp compares hexant's stills with
// POV-Ray 3.7's.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 20, -100> look_at <0, 18, 0> angle 60 }
plane { z, 50 pigment { checker rgb <0, 0, 1> rgb <0, 1, 0> scale 20 } finish { ambient 0.2 diffuse 0.8 } hollow }
#declare Glow = media {
  emission 0.05 intervals 1 samples 5 method 3
  density { spherical color_map { [0 rgb 0] [0.1 rgb <1, 0, 0>] [1 rgb <1, 1, 0>] } }
}
sphere { <-29, 20 + 4 * clock, 0>, 20
  pigment { rgbt <1, 1, 1, 0.9> } finish { ambient 0 diffuse 0 phong 1 phong_size 200 }
  interior { ior 1.1 } hollow no }
sphere { 0, 1 pigment { rgbf 1 } finish { ambient 0 diffuse 0 }
  interior { media { Glow } } scale 28 translate <-29, 20, 0> hollow }
sphere { <29, 20, 0>, 20
  pigment { rgbt <1, 1, 1, 0.9> } finish { ambient 0 diffuse 0 phong 1 phong_size 200 }
  interior { ior 1.1 } hollow yes }
sphere { 0, 1 pigment { rgbf 1 } finish { ambient 0 diffuse 0 }
  interior { media { Glow } } scale 28 translate <29, 20, 0> hollow }
light_source { <500, 600, -200>, rgb 1 }
