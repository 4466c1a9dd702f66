// Shadows through objects that filter and transmit (POV-Ray 3.7's
// ComputeShadowColour): a red filtering ball (its two surfaces each filter),
// a transmitting box, a pane whose checker is half clear, a layered
// texture, a texture_map half opaque, and a clear ball that casts no
// shadow; they move with clock. tests/tracer/pov_reference_test.cpp
// compares hexant's stills with POV-Ray 3.7's (README.md, "Lights").
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -7> look_at <0, 0, 0> angle 55 }
light_source { <-2, 9, -3>, rgb 1 }
light_source { <4, 6, 2>, rgb <0.4, 0.4, 0.5> }
background { rgb <0.2, 0.25, 0.35> }
plane { y, 0 pigment { rgb 0.9 } }
sphere { <-2 + clock, 1, 0>, 0.8 pigment { rgbf <1, 0.3, 0.2, 0.8> } finish { phong 0.6 } }
box { <-0.5, 0, -0.5>, <0.5, 1.2, 0.5> rotate y * (20 + 40 * clock) translate <0.3, 0, 1.5>
      pigment { rgbt <0.3, 0.5, 1, 0.6> } }
box { <-1.2, 0, -0.02>, <1.2, 1.5, 0.02> translate <2, 0, -0.5 + clock>
      pigment { checker rgbf <0.2, 1, 0.3, 0.9>, rgb <1, 1, 0.5> scale 0.3 } }
sphere { <0, 0.6, -1.5 + 0.5 * clock>, 0.6
         texture { pigment { rgbt <1, 1, 1, 0.9> } }
         texture { pigment { rgbf <0.9, 0.5, 1, 0.7 - 0.4 * clock> } } }
cylinder { <-2.5, 0, 2>, <-2.5, 1.4, 2>, 0.5
           texture { gradient y texture_map { [0.5 pigment { rgbf <1, 1, 0, 0.8> }] [0.5 pigment { rgb <0.2, 0.6, 0.2> }] } } }
sphere { <2.5, 0.5, 2 - clock>, 0.5 pigment { rgbt <0.5, 0.5, 0.5, 0.5> } no_shadow }
