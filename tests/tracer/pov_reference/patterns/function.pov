// function: POV-Ray 3.7's function pattern (pattern.cpp's
// FunctionPattern::EvaluateRaw: a value above 1 wrapped by fmod) and its
// pigment functions (`function { pigment { } }`, read by .red, .gray, ...):
// a floor whose pattern is a user function moving with clock, a ball whose
// normal is a function pattern, a ball whose texture_map is picked by one,
// and a box whose pigment averages three function patterns that read a
// pigment function's channels (colors.inc's gamma-correcting idiom, as
// the distribution's woods scenes write it). The kinds are
// runtime/texture/pattern/kinds/function.hpp and
// runtime/texture/pigment_function.hpp; tests/tracer/pov_reference_test.cpp
// compares hexant's stills with POV-Ray 3.7's.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -4> look_at <0, 0, 0.5> angle 60 }
light_source { <-3, 6, -5>, rgb 1 }
#declare Wave = function(a, b) { sin(a * 3 + clock * 2) * 0.5 + 0.5 + b }
#declare Pig = function { pigment { checker rgb <1, 0.2, 0>, rgb <0, 0.4, 1> scale 0.5 } }
plane { y, 0
  pigment { function { Wave(x, z * 0.3) + 0.2 * Pig(x, y, z).gray }
    color_map { [0 rgb <0.1, 0.1, 0.4>] [0.5 rgb <0.9, 0.8, 0.2>] [1 rgb <0.2, 0.6, 0.2>] } }
  finish { ambient 0.6 diffuse 0.4 } }
sphere { <1.2, 0.8, 0>, 0.7
  pigment { rgb 0.8 }
  normal { function { abs(sin(x * 8)) * (1 + clock) } 0.6 } }
sphere { <-1.2, 0.8, 0>, 0.7
  texture { function { y * 0.8 + clock * 0.3 }
    texture_map {
      [0.3 pigment { rgb <1, 0.5, 0> } finish { phong 1 }]
      [0.7 pigment { rgb <0.2, 0.2, 1> } finish { ambient 0.3 }]
    } } }
#macro Correct_Pigment_Gamma(Orig_Pig, New_G)
  #local Correct_Pig_fn = function { pigment { Orig_Pig } }
  pigment { average pigment_map {
    [function { pow(Correct_Pig_fn(x, y, z).x, New_G) } color_map { [0 rgb 0] [1 rgb <3, 0, 0>] }]
    [function { pow(Correct_Pig_fn(x, y, z).y, New_G) } color_map { [0 rgb 0] [1 rgb <0, 3, 0>] }]
    [function { pow(Correct_Pig_fn(x, y, z).z, New_G) } color_map { [0 rgb 0] [1 rgb <0, 0, 3>] }]
  } }
#end
box { <-0.5, 0, 1.2>, <0.5, 1, 2.2>
  texture { Correct_Pigment_Gamma(pigment { gradient x color_map { [0 rgb <0.2, 0.5, 0.9>] [1 rgb <0.9, 0.6, 0.1>] } }, 2.2)
    finish { ambient 0.5 diffuse 0.5 } } }
