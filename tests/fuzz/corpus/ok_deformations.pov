// hexant's deformations (not POV-Ray SDL, so this scene is for hexant only):
// flags: --frame-count 16 --clock 0:1
// twist, taper and bend as object modifiers, constant or changing with
// clock, alone, combined, after transforms, inside CSG and through macros.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -12> look_at <0, 1, 0> }
light_source { <5, 10, -10>, White }

box { <-0.5, 0, -0.5>, <0.5, 3, 0.5> twist y, 90 pigment { Red } translate -4 * x }
box { <-0.5, 0, -0.5>, <0.5, 3, 0.5> twist y, 360 * clock pigment { Green } translate -2 * x }
cylinder { 0, 3 * y, 0.5 taper y, 0.5 pigment { Blue } }
cylinder { 0, 3 * y, 0.5 taper y, 1 - 0.5 * clock pigment { Yellow } translate 2 * x }
box { <-0.25, 0, -0.25>, <0.25, 3, 0.25> bend x, 30 pigment { Orange } translate 4 * x }
box { <-0.25, 0, -0.25>, <0.25, 3, 0.25> bend z, 60 * sin(2 * pi * clock) pigment { Cyan } translate 6 * x }
box { <-0.5, 0, -0.5>, <0.5, 2, 0.5> scale <1, 1.5, 1> twist y, 45 taper y, 0.5 bend x, 20 translate -6 * x }
union {
  box { <-1, 0, -0.2>, <1, 0.4, 0.2> }
  sphere { y, 0.3 }
  twist x, 180 * clock
  translate <0, 0.5, 3>
}
#macro Wobbly(Where, Turn)
  cone { 0, 0.6, 2 * y, 0.1 twist y, Turn bend x, Turn / 4 translate Where }
#end
Wobbly(<-3, 0, 4>, 120)
Wobbly(<3, 0, 4>, 720 * clock)
plane { y, 0 pigment { checker White, Gray50 } }

