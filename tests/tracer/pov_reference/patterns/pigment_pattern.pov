// pigment_pattern: POV-Ray 3.7's pigment as a pattern (pattern.cpp's
// pigment_pattern: the pigment's grey, 0.297 r + 0.589 g + 0.114 b): a
// checker's colours as greys through a colour map (frequency 2 wrapping
// them), a pigment_map picked by a gradient pigment's grey under
// turbulence, a normal from a bozo pigment's grey (its amount after the
// block) and from an average of pigments, and a texture_map picked by a
// pigment moving with clock. The kind is
// runtime/texture/pattern/kinds/pigment_pattern.hpp;
// tests/tracer/pov_reference_test.cpp compares hexant's stills with POV-Ray
// 3.7's (README.md, "Patterns").
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -4> look_at <0, 0, 0.5> angle 60 }
light_source { <-3, 6, -5>, rgb 1 }
plane { y, 0
  pigment { pigment_pattern { checker rgb <1, 0, 0>, rgb <0.2, 0.9, 1> scale 0.5 }
    frequency 2 color_map { [0 rgb 0] [1 rgb <1, 1, 0>] } rotate y * 20 }
  finish { ambient 0.6 diffuse 0.4 } }
sphere { <1.2, 0.8, 0>, 0.7
  pigment { rgb 0.8 }
  normal { pigment_pattern { bozo color_map { [0 rgb 0] [1 rgb <1, 0.5, 0>] } scale 0.2 }, 0.8 } }
sphere { <-1.2, 0.8, 0>, 0.7
  pigment { pigment_pattern { gradient x color_map { [0 rgb 0] [1 rgb 1] } turbulence 0.3 }
    pigment_map { [0.3 rgb <1, 0, 0>] [0.7 checker rgb 0, rgb 1 scale 0.2] }
    scale 0.5 } }
sphere { <0, 0.5, -1.2>, 0.45
  pigment { rgb 0.9 }
  normal { pigment_pattern { average
      pigment_map { [1 gradient x sine_wave] [1 gradient y sine_wave] [3 bumps] }
      scale 0.2 } 2 } }
box { <-0.5, 0, 1.2>, <0.5, 1.6, 1.6>
  texture { pigment_pattern { onion color_map { [0 rgb 0] [1 rgb <0, 1, 1>] } translate x * clock scale 0.4 }
    texture_map {
      [0.4 pigment { rgb <1, 0, 0> } finish { phong 1 }]
      [0.6 pigment { rgb <0, 0, 1> } normal { bumps 0.5 scale 0.1 }]
    } } }
