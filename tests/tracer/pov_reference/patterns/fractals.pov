// fractals: POV-Ray 3.7's fractal patterns (pattern.cpp's mandel_pattern,
// mandel3/4/x_pattern, julia_pattern, julia3/4/x_pattern, the four magnet
// patterns, fractal_exterior_color and fractal_interior_color; Parse_Pattern's
// MANDEL, JULIA, MAGNET, EXTERIOR, INTERIOR and EXPONENT tokens), one tile
// each: mandel with every exterior type (0 to 8) and interior type (0 to 6),
// its default map and the grey one of another exponent, exponents 3, 4 and
// 7, julia with exponents 2, 3 and 5, magnet 1 and 2 in their mandel and
// julia forms, a julia point, iterations and a factor moving with clock,
// fractals as normals, in a texture_map and under turbulence, frequency and
// a wave. The kinds are runtime/texture/pattern/kinds/mandel.hpp, julia.hpp
// and magnet.hpp; tests/tracer/pov_reference_test.cpp compares hexant's
// stills with POV-Ray 3.7's (README.md, "Patterns").
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <4, 3, -10> look_at <4, 3, 0> right 8 * x up 6 * y }
light_source { <-20, 30, -40>, rgb 1 }
#declare M = color_map {
  [0 rgb <0, 0, 0.3>] [0.25 rgb <0, 0.6, 1>] [0.5 rgb <1, 1, 0.3>]
  [0.75 rgb <1, 0.3, 0>] [1 rgb 1] }
#declare Flat = finish { ambient 1 diffuse 0 }
#macro Tile(I, J, P)
  box { <I, J, 0>, <I + 1, J + 1, 1>
    texture { pigment { P translate <I + 0.5, J + 0.5, 0> } finish { Flat } } }
#end
// The Mandelbrot set's box [-2, 0.5] x [-1.25, 1.25] in a tile.
#declare Set = transform { scale 0.4 translate 0.3 * x }
// Its main cardioid, for the interior types.
#declare Heart = transform { translate 0.3 * x scale 0.8 }
// row 5: exterior types 0 to 7
Tile(0, 5, pigment { mandel 12 exterior 0, 0.3 color_map { M } transform Set })
Tile(1, 5, pigment { mandel 12 exterior 1, 1 color_map { M } transform Set })
Tile(2, 5, pigment { mandel 12 exterior 2, 0.25 color_map { M } transform Set })
Tile(3, 5, pigment { mandel 12 exterior 3, 0.25 color_map { M } transform Set })
Tile(4, 5, pigment { mandel 12 exterior 4, 0.1 color_map { M } transform Set })
Tile(5, 5, pigment { mandel 12 exterior 5, 0.1 color_map { M } transform Set })
Tile(6, 5, pigment { mandel 12 exterior 6, 0.2 color_map { M } transform Set })
Tile(7, 5, pigment { mandel 12 exterior 7, 4 color_map { M } transform Set })
// row 4: exterior type 8, interior types 0 to 6
Tile(0, 4, pigment { mandel 12 exterior 8, 3 color_map { M } transform Set })
Tile(1, 4, pigment { mandel 15 interior 0, 0.4 color_map { M } transform Heart })
Tile(2, 4, pigment { mandel 15 interior 1, 1.5 color_map { M } transform Heart })
Tile(3, 4, pigment { mandel 15 interior 2, 1 color_map { M } transform Heart })
Tile(4, 4, pigment { mandel 15 interior 3 1 color_map { M } transform Heart })
Tile(5, 4, pigment { mandel 15 interior 4, 2 color_map { M } transform Heart })
Tile(6, 4, pigment { mandel 15 interior 5, 2 color_map { M } transform Heart })
Tile(7, 4, pigment { mandel 15 exterior 0, 0 interior 6, 1 color_map { M } transform Heart })
// row 3: the default maps, exponents, julia
Tile(0, 3, pigment { mandel 25 transform Set })
Tile(1, 3, pigment { mandel 10 exponent 3 scale 0.35 })
Tile(2, 3, pigment { mandel 10 exponent 4 color_map { M } scale 0.35 })
Tile(3, 3, pigment { mandel 8 exponent 7 exterior 6, 0.3 color_map { M } scale 0.4 })
Tile(4, 3, pigment { julia <0.353, 0.288>, 30 color_map { M } scale 0.3 })
Tile(5, 3, pigment { julia <0.4, 0.1> 20 exponent 3 interior 1, 1 color_map { M } scale 0.35 })
Tile(6, 3, pigment { julia <-0.6, 0.4>, 12 exponent 5 exterior 2, 0.5 color_map { M } scale 0.35 })
Tile(7, 3, pigment { julia <-0.8, 0.156>, 25 exponent 2 exterior 6, 0.3 interior 1, 2 color_map { M } scale 0.3 })
// row 2: magnets, and numbers moving with clock
Tile(0, 2, pigment { magnet 1 mandel 12 color_map { M } scale 0.12 translate -0.1 * x })
Tile(1, 2, pigment { magnet 2 mandel 12 color_map { M } scale 0.12 translate -0.1 * x })
Tile(2, 2, pigment { magnet 1 julia <1.6, 0.4>, 15 color_map { M } scale 0.15 translate -0.1 * x })
Tile(3, 2, pigment { magnet 2 julia <1.2, 0.3> 15 color_map { M } scale 0.15 translate -0.1 * x })
Tile(4, 2, pigment { magnet 1 mandel 20 exterior 6, 0.05 interior 1, 1 color_map { M } scale 0.12 })
Tile(5, 2, pigment { magnet 2 julia <1.5, 0.8>, 20 exterior 2, 0.2 interior 2, 1 color_map { M } scale 0.15 })
Tile(6, 2, pigment { julia <0.353 + 0.3 * clock, 0.288>, 16 + 20 * clock color_map { M } scale 0.3 })
Tile(7, 2, pigment { mandel 12 exterior 2, 0.25 + 0.5 * clock color_map { M } transform Set })
// row 1: as normals, in a texture_map
#macro Bumpy(I, J, N)
  box { <I, J, 0>, <I + 1, J + 1, 1>
    texture { pigment { rgb 0.9 } normal { N translate <I + 0.5, J + 0.5, 0> }
      finish { ambient 0.15 diffuse 0.85 } } }
#end
Bumpy(0, 1, normal { mandel 20, 0.6 transform Set })
Bumpy(1, 1, normal { julia <0.353, 0.288>, 20 exterior 6, 0.5 bump_size 0.8 scale 0.3 })
Bumpy(2, 1, normal { magnet 1 mandel 12, 0.5 scale 0.12 })
Bumpy(3, 1, normal { mandel 10 exponent 3 interior 1, 1 scale 0.35 })
box { <4, 1, 0>, <6, 2, 1>
  texture { mandel 20 exterior 1, 1
    texture_map {
      [0.2 pigment { rgb <0.1, 0.2, 0.6> } finish { Flat }]
      [0.2 pigment { rgb <1, 0.8, 0.2> } finish { Flat }]
      [1 pigment { rgb <0.9, 0.1, 0.1> } finish { Flat }]
    }
    scale 0.8 translate <5.6, 1.5, 0> } }
Tile(6, 1, pigment { julia <0.285, 0.01>, 40 color_map { M } scale 0.3 rotate 30 * z })
Tile(7, 1, pigment { magnet 2 mandel 10 + 10 * clock color_map { M } scale 0.12 })
// row 0: with the patterns' modifiers
Tile(0, 0, pigment { mandel 20 color_map { M } turbulence 0.1 transform Set })
Tile(1, 0, pigment { mandel 20 color_map { M } frequency 3 phase 0.2 transform Set })
Tile(2, 0, pigment { julia <0.353, 0.288>, 30 color_map { M } sine_wave scale 0.3 })
Tile(3, 0, pigment { mandel 20 exterior 6, 0.2 interior 1, 1 color_map { M } warp { turbulence 0.2 } transform Heart })
Tile(4, 0, pigment { julia <-0.75, 0.1>, 30 exterior 1, 1 interior 4, 3 color_map { M } scale <0.5, 0.25, 1> })
Tile(5, 0, pigment { magnet 1 julia <2.2, 0>, 20 exterior 3, 0.3 interior 3, 1 color_map { M } scale 0.15 })
Tile(6, 0, pigment { magnet 2 mandel 20 exterior 8, 4 color_map { M } scale 0.12 translate -0.1 * x })
Tile(7, 0, pigment { mandel 30 exterior 7, 5 interior 1, 2 color_map { M } scale 0.12 translate <0.1, 0.15, 0> })
