// light_group as POV-Ray 3.7 renders it: a group's lights light only its
// members (global_lights off: not the scene's light either); a group with
// global_lights on; a declared group placed twice, each copy with its own
// light; a group nested in another, lit by both groups' lights; a
// difference of two groups, each surface lit by its own group's light;
// lights and members moving with clock. Shadows fall from every object.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.5, 0> angle 55 }
light_source { <-6, 10, -8> rgb 0.6 }
background { rgb 0.05 }
plane { y, -1 pigment { checker rgb 0.7, rgb 0.4 } }
light_group {
  light_source { <0, 6, -4> rgb <1, 0.2, 0.2> }
  sphere { <-3, 0, 0>, 0.8 pigment { rgb 1 } }
  translate x * clock
}
light_group {
  light_source { <3, 3, -6> rgb <0.2, 0.3, 1> }
  box { <-0.7, -1, -0.7>, <0.7, 0.6, 0.7> pigment { rgb 1 } rotate y * (20 + 40 * clock) }
  global_lights on
}
#declare Lit = light_group {
  light_source { <0, 2, -3> rgb <0.2, 1, 0.3> }
  cylinder { <0, -1, 0>, <0, 0.2, 0>, 0.4 pigment { rgb 1 } }
}
object { Lit translate <-1.2, 0, 2.5> }
object { Lit translate <1.2, 0.3 * clock, 2.5> }
// (Nested as POV-Ray's documentation writes it, a declared group inside:
// its members are lit by both. POV-Ray 3.7 lights the members of a group
// written out inside another by the inner group's lights alone, a quirk
// of its Promote_Local_Lights that hexant does not keep.)
#declare Inner = light_group {
  light_source { <6, 1, -2> rgb <1, 0.8, 0> }
  sphere { <3, 1.4, 0>, 0.5 pigment { rgb 1 } }
}
light_group {
  light_source { <0, 8, 0> rgb 0.5 }
  sphere { <3, 0.2, 0>, 0.6 pigment { rgb 1 } }
  object { Inner }
}
difference {
  light_group {
    sphere { 0, 1 pigment { rgb 1 } }
    light_source { <-100, 0, -100> rgb <1, 0, 0> }
  }
  light_group {
    sphere { <0, 1, 0>, 1 pigment { rgb 1 } }
    light_source { <100, 100, 0> rgb <0, 0, 1> }
  }
  rotate <-45, 0, 0>
  scale 0.7
  translate <1.4 + 0.6 * clock, 0.2, -2.6>
}
