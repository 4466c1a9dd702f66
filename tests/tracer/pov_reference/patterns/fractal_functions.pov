// functions.inc's fractal noises, whose octaves count a loop (hexant
// makes their bodies per call: language/function_internals.cpp):
// f_ridged_mf (advanced/balcony's water), f_hetero_mf and f_ridge, each
// as a pigment's pattern on a band of a plane seen from above, with
// non-integer octaves where the function reads their fraction, and a
// second noise generator. (Both f_ridged_mf calls have the same H and
// lacunarity: POV-Ray keeps the octaves' weights of the function's first
// evaluation for every later call, whatever their H and lacunarity;
// hexant computes each call's own.) Against POV-Ray 3.7 (tests/tracer/
// pov_reference_test.cpp).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare f_hetero_mf = function { internal(29) }
#declare f_ridge = function { internal(58) }
#declare f_ridged_mf = function { internal(59) }
camera { orthographic location <0, 10, 0> sky z look_at 0 right 8 * x up 6 * z }
#declare RMF = function { f_ridged_mf(x, y, z, 0.07, 2.2, 7, 0.6, 0.9, 1) }
#declare RMF2 = function { f_ridged_mf(x, y, z, 0.07, 2.2, 8, 0.7, 0.8, 2) }
#declare HMF = function { f_hetero_mf(x, y, z, 0.5, 2, 6.5, 0.3, 2, 2) }
#declare RDG = function { f_ridge(x, y, z, 2.1, 5.5, 0.6, 0.2, 0.3, 1) }
#declare Map = color_map { [0 rgb <0.1, 0.1, 0.3>] [0.5 rgb <0.9, 0.5, 0.2>] [1 rgb 1] }
plane { y, 0
  pigment { function { RMF(x + clock, y, z) * 0.5 } color_map { Map } }
  finish { ambient 1 diffuse 0 }
  clipped_by { box { <-5, -1, 1.5>, <5, 1, 4> } } }
plane { y, 0
  pigment { function { RMF2(x, y, z) * 0.4 } color_map { Map } }
  finish { ambient 1 diffuse 0 }
  clipped_by { box { <-5, -1, 0>, <5, 1, 1.5> } } }
plane { y, 0
  pigment { function { HMF(x, y, z) * 0.5 + 0.3 } color_map { Map } }
  finish { ambient 1 diffuse 0 }
  clipped_by { box { <-5, -1, -1.5>, <5, 1, 0> } } }
plane { y, 0
  pigment { function { RDG(x * 2, y, z * 2) + 0.5 } color_map { Map } }
  finish { ambient 1 diffuse 0 }
  clipped_by { box { <-5, -1, -4>, <5, 1, -1.5> } } }
