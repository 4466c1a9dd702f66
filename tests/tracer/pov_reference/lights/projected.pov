// projected_through: a spotlight-like beam cut by a ring and a box it
// shines through (moving with clock), the box's twin in the scene not
// shadowing it; a shadowless light projected through a sphere; a ball in
// the beam casting its shadow on the floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.5, 0> }
#declare Gobo = union {
  torus { 0.5, 0.1 }
  box { <-0.2, -0.05, -0.2>, <0.2, 0.05, 0.2> rotate y * 30 translate x * 0.8 }
  translate <0.3 * clock, 3, 0>
}
object { Gobo pigment { rgb <0.8, 0.6, 0.2> } }
light_source { <0, 6, 0>, rgb 1.5 projected_through { Gobo } }
light_source { <-3, 4, -3>, rgb 0.4 shadowless projected_through { sphere { <-1.5, 2, -1.5>, 0.6 } } }
light_source { <5, 8, -8>, rgb 0.2 }
plane { y, 0 pigment { checker rgb 0.9, rgb 0.6 } }
sphere { <0.4, 0.4, 0.2>, 0.4 pigment { rgb <0.2, 0.4, 0.9> } }
