// warps: POV-Ray 3.7's warps other than turbulence (warps.cpp's
// Warp_EPoint, parstxtr.cpp's Parse_Warp): repeat with offset and flip,
// black_hole (inverse; with repeat and turbulence, whose centres come from
// WarpRands), planar, cylindrical, spherical, toroidal and cubic, one
// object each, and a normal read through a repeat warp between transforms
// (which turn it; the repeat does not). The repeat's offset, a black
// hole's strength, the planar distance and the torus's major radius move
// with clock. The warps are runtime/texture/pattern/warps/;
// tests/tracer/pov_reference_test.cpp compares hexant's stills with
// POV-Ray 3.7's (README.md, "Patterns").
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -10> look_at <0, 0, 0> angle 45 }
light_source { <-6, 8, -10>, rgb 1 }
#declare F = finish { ambient 0.4 diffuse 0.6 }
#declare Warm = color_map { [0 rgb <0.9, 0.3, 0.1>] [0.5 rgb <1, 0.9, 0.4>] [1 rgb <0.2, 0.3, 0.8>] }
// repeat along x, each copy moved up by the offset, odd copies mirrored in y
box { <-0.95, -0.95, 0>, <0.95, 0.95, 0.2>
  pigment { bozo color_map { Warm } scale 0.25
    warp { repeat x * 0.6 offset <0, 0.2 + 0.3 * clock, 0> flip y } }
  finish { F } translate <-2.4, 1.9, 0> }
// a black hole pushing a checker out from the panel's centre
box { <-0.95, -0.95, 0>, <0.95, 0.95, 0.2>
  pigment { checker rgb <1, 0.8, 0.2>, rgb <0.1, 0.2, 0.5> scale 0.2
    warp { black_hole <0, 0, 0>, 0.85 falloff 2 strength 1.2 + clock inverse } }
  finish { F } translate <0, 1.9, 0> }
// repeated black holes, their centres jittered by turbulence
box { <-0.95, -0.95, 0>, <0.95, 0.95, 0.2>
  pigment { checker rgb <0.95, 0.95, 0.95>, rgb <0.7, 0.2, 0.5> scale 0.1
    warp { black_hole <0.1, 0.1, 0>, 0.25 falloff 1.5 strength 1
      repeat <0.55, 0.55, 0> turbulence <0.15, 0.1, 0> }
    translate <-1, -1, 0> }
  finish { F } translate <2.4, 1.9, 0> }
// planar: the pattern of the plane y = -distance, seen across x and z
sphere { 0, 0.95
  pigment { granite color_map { Warm } scale 1.5
    warp { planar <0, 1, 0>, 0.4 * clock } }
  finish { F } translate <-2.4, 0, 0> }
// cylindrical about y, the angle scaled by the distance
sphere { 0, 0.95
  pigment { checker rgb <0.9, 0.9, 0.9>, rgb <0.6, 0.1, 0.1> scale <0.125, 0.3, 0.3>
    warp { cylindrical orientation <0, 1, 0> dist_exp 0.5 } }
  finish { F } rotate x * -30 translate <0, 0, 0> }
// spherical: longitude and latitude
sphere { 0, 0.95
  pigment { checker rgb <0.1, 0.5, 0.2>, rgb <0.95, 0.95, 0.7> scale <1 / 12, 1 / 6, 1>
    warp { spherical } }
  finish { F } rotate <-20, 30, 0> translate <2.4, 0, 0> }
// toroidal around a tube of major radius 0.7 (0.75 at clock 0.5)
torus { 0.7, 0.25
  pigment { checker rgb <0.2, 0.2, 0.7>, rgb <1, 0.6, 0.2> scale <1 / 16, 1 / 4, 1>
    warp { toroidal major_radius 0.7 + 0.1 * clock } }
  finish { F } rotate x * -60 translate <-2.4, -1.9, 0> }
// cubic: each face of the cube unfolded
box { -0.7, 0.7
  pigment { checker rgb <0.95, 0.95, 0.95>, rgb <0.3, 0.5, 0.9> scale <1 / 16, 1 / 12, 1>
    warp { cubic } }
  finish { F } rotate <25, -35, 0> translate <0, -1.9, 0> }
// a normal through a repeat warp, between a scale and a turn
sphere { 0, 0.95
  pigment { rgb <0.8, 0.75, 0.7> }
  normal { bumps 1.5 scale <0.15, 0.3, 0.15> warp { repeat x * 0.4 flip x } rotate z * 30 }
  finish { F } translate <2.4, -1.9, 0> }
