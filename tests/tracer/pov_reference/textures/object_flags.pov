// Which rays see an object (no_image, no_reflection: POV-Ray's kinds of
// rays, a refracted ray counting as the ray it came from) and
// double_illuminate (a disc lit from behind, its shadow ray leaving the
// back). The no_image sphere still casts its shadow and shows in the
// mirror; the no_reflection one shows but not in the mirror; through the
// glass the no_image one stays hidden. A union's flag reaches its members.
// tests/tracer/pov_reference_test.cpp compares hexant's stills with
// POV-Ray 3.7's (README.md, "Objects").
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.8, -6> look_at <0, 0.5, 0> angle 60 }
light_source { <-3, 6, -5>, rgb 1 }
light_source { <2, 1, 4>, rgb <0.6, 0.5, 0.3> }
plane { y, -0.5 pigment { checker rgb <0.1, 0.2, 0.5> rgb 0.9 } finish { ambient 0.2 } }
box { <-3, -0.5, 2>, <3, 2.5, 2.1> pigment { rgb 0.2 } finish { reflection 0.8 } }
sphere { <-2, 0.2 + 0.4 * clock, 0>, 0.6 pigment { rgb <0.9, 0.2, 0.1> } no_image }
sphere { <-0.5, 0.2, 0.5>, 0.5 pigment { rgb <0.1, 0.8, 0.2> } no_reflection }
union { sphere { <0.8, 0.9, -0.2>, 0.3 } sphere { <1.4, 0.9, -0.2>, 0.3 }
  pigment { rgb <0.9, 0.8, 0.1> } no_reflection }
sphere { <0.3, 0.1, -1.6>, 0.5 pigment { rgbf <1, 1, 1, 0.95> } interior { ior 1.3 } }
sphere { <0.2, 0.2, -0.2>, 0.25 pigment { rgb <0.9, 0.1, 0.9> } no_image }
disc { <2, 0.6, 0.5>, <-0.3, 0, 1>, 0.7 pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0 diffuse 0.8 } double_illuminate }
disc { <2.6, 0.6, -0.8>, <-0.3, 0, 1>, 0.4 pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0 diffuse 0.8 } }
