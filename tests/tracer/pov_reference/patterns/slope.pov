// slope: POV-Ray 3.7's slope pattern (pattern.cpp's slope_pattern,
// Parse_Pattern's SLOPE_TOKEN): the short form, the block with a slope
// range and an altitude range (slopemt's kind, a texture_map), point_at,
// a slope turned and scaled (the transforms move the altitude, not the
// normal it reads), a slope read after a bumpy normal (the perturbed
// normal, POV-Ray's PNormal) and one moving with clock. The kind is
// runtime/texture/pattern/kinds/slope.hpp; tests/tracer/pov_reference_test.cpp
// compares hexant's stills with POV-Ray 3.7's (README.md, "Patterns").
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -4> look_at <0, 0, 0.5> angle 60 }
light_source { <-3, 6, -5>, rgb 1 }
plane { y, 0 pigment { slope { y, 0, 1 + clock altitude <0, 0, 1>, -1, 3 } } finish { ambient 0.6 diffuse 0.4 } }
sphere { <1.2, 0.8, 0>, 0.7
  pigment { slope y color_map { [0 rgb <1, 0, 0>] [0.5 rgb <0, 1, 0>] [1 rgb <0, 0, 1>] } } }
sphere { <-1.2, 0.8, 0>, 0.7
  texture { slope { -y * 3, 0, 0.5 altitude y, 0.2, 1.4 }
    texture_map {
      [0.45 pigment { rgb <0.2, 0.6, 0.1> }]
      [0.55 pigment { rgb <0.5, 0.3, 0.1> }]
      [0.65 pigment { rgb <0.5, 0.3, 0.1> }]
      [0.65 pigment { rgb 0.9 } finish { phong 1 }]
    } } }
sphere { <0, 0.5, -1.2>, 0.45
  pigment { slope { point_at <3, 4, -3> } color_map { [0 rgb 0] [1 rgb <1, 1, 0>] } } }
sphere { <0.3, 0.6, 1.6>, 0.6
  pigment { slope { x + z * clock, 0.2, 0.8 } scale 2 rotate z * 40 color_map { [0 rgb <1, 0, 1>] [1 rgb <0, 1, 0>] } }
  normal { bumps 0.8 scale 0.15 } }
