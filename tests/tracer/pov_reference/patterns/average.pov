// average: POV-Ray 3.7's averaged maps (pigment.cpp's Do_Average_Pigments,
// normal.cpp's Do_Average_Normals, trace.cpp's ComputeAverageTextureColours):
// a pigment_map averaged by its weights (one moving with clock) in the
// average's own transformed space, a normal_map of three normals averaged,
// and a texture_map of two textures lit each on its own (one with phong)
// and averaged. The kind is runtime/texture/pattern/kinds/average.hpp;
// tests/tracer/pov_reference_test.cpp compares hexant's stills with POV-Ray
// 3.7's (README.md, "Patterns").
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -4> look_at <0, 0, 0.5> angle 60 }
light_source { <-3, 6, -5>, rgb 1 }
plane { y, 0
  pigment { average
    pigment_map {
      [1 checker rgb <1, 0, 0>, rgb <0, 0, 1>]
      [2 + 2 * clock gradient x color_map { [0 rgb 0] [1 rgb <0, 1, 0>] }]
      [0.5 rgb <1, 1, 0>]
    }
    scale 0.5 rotate y * 30 }
  finish { ambient 0.6 diffuse 0.4 } }
sphere { <1.2, 0.8, 0>, 0.7
  pigment { rgb 0.8 }
  normal { average
    normal_map {
      [1 gradient x, 0.8 scale 0.2]
      [3 bumps 0.6 scale 0.1]
      [1 + clock wrinkles 0.5 scale 0.3]
    }
    rotate z * 20 } }
sphere { <-1.2, 0.8, 0>, 0.7
  texture { average
    texture_map {
      [1 pigment { rgb <1, 0.5, 0> } finish { phong 1 }]
      [3 pigment { radial frequency 6 } normal { bumps 0.5 scale 0.1 } finish { ambient 0.3 }]
    }
    rotate x * 90 } }
