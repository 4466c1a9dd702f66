// isosurface_pigment: isosurfaces whose functions call pigment functions
// (`function { pigment { } }`), which have no interval bound, so hexant
// searches them as POV-Ray does, by max_gradient
// (runtime/objects/isosurface/isosurface_geometry.hpp): a slab whose top is
// crackle's relief, the pattern moving with clock; a ball with bozo's
// bumps in a sphere container; an open box of ripples under a
// threshold. tests/tracer/pov_reference_test.cpp compares hexant's stills
// with POV-Ray 3.7's.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -4.5> look_at <0, 0.2, 0.5> angle 55 }
light_source { <-3, 6, -5>, rgb 1 }
plane { y, -0.6 pigment { checker rgb 0.3 rgb 0.8 } }
#declare Crack = function { pigment { crackle color_map { [0 rgb 0] [1 rgb 1] } scale 0.4 translate x * clock } }
#declare Bump = function { pigment { bozo color_map { [0 rgb 0] [1 rgb 1] } scale 0.3 } }
#declare Ridge = function { pigment { ripples color_map { [0 rgb 0] [1 rgb 1] } scale 0.4 } }
isosurface {
  function { y - Crack(x, 0, z).red * 0.4 }
  contained_by { box { <-1, -0.5, -1>, <1, 0.5, 1> } }
  max_gradient 3
  pigment { rgb <0.9, 0.5, 0.3> }
  translate <-1.2, 0, 1.2> }
isosurface {
  function { sqrt(x * x + y * y + z * z) - 0.6 - Bump(x, y, z).gray * 0.25 }
  contained_by { sphere { 0, 1 } }
  max_gradient 3
  pigment { rgb <0.4, 0.6, 0.9> }
  translate <1.2, 0.3, 1.2> }
isosurface {
  function { y + Ridge(x, 0, z).red * 0.5 }
  threshold 0.2
  contained_by { box { <-0.6, -0.5, -0.4>, <0.6, 0.5, 0.4> } }
  open
  max_gradient 6
  pigment { rgb <0.6, 0.9, 0.5> }
  translate <0, 0, -0.9> }
