// Case 07 (../shared/cases/2026-12-03/07-if-clock-inside-object, reduced):
// `#if (clock >= 0.5)` inside a sphere's block choosing its pigment and
// finish (the colour then grows with clock), and an #if on clock whose two
// branches each add a cone, texture the union and close it. Copies of the
// pawn move with clock.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 1, 0> angle 45 }
light_source { <-5, 10, -8> color rgb 1 }
plane { y, 0 pigment { checker rgb <0.5, 0.6, 0.9> rgb 1 } finish { reflection 0.2 } }
#declare Pawn = union {
sphere { <0, 1, 0>, 0.35
#if (clock >= 0.5)
  pigment { color rgbf <0.5 + clock, clock, 0.2, 0> }
  finish { phong 0.8 reflection 0.3 }
#else
  pigment { color rgbf <1, 0, 0, 0> }
  finish { phong 0.8 } #end
}
#if (clock >= 0.5)
cone { <0, 0, 0>, 0.5, <0, 1, 0>, 0 }
texture { pigment { color rgb <0.2, 0.4 + clock * 0.5, 0.3> } finish { phong 0.5 } } }
#else
cone { <0, 0, 0>, 0.5, <0, 1.2, 0>, 0 }
texture { pigment { color rgb <1, 0.5, 0.5> } finish { phong 0.5 } } }
#end
union {
  object { Pawn translate <-1.5, 0, clock * 2> }
  object { Pawn translate <0, clock, 0> }
  object { Pawn translate <1.5, 0, -clock> }
}
