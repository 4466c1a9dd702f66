// min_extent and max_extent against POV-Ray 3.7 (tests/tracer/pov_reference_test.cpp,
// clock 0 and 0.5): a text centred on its box as shapes.inc's Center_Object
// does it (written out here: the tests do not need povray-includes), a
// countdown text from str(clock) whose box changes with its string (piecewise
// in time), a turned box set on its lowest corner, and a ball at a text's
// upper corner.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -6> look_at <0, 0.5, 0> angle 50 }
light_source { <-5, 8, -6> color rgb 1 }
background { rgb <0.1, 0.1, 0.2> }
plane { y, -0.5 pigment { checker rgb 0.8, rgb 0.4 } }
#macro Centred(O, Axes)
  object { O translate -(min_extent(O) + max_extent(O)) / 2 * Axes }
#end
#declare T = text { ttf "timrom.ttf" "Centre" 0.2, 0 }
object { Centred(T, x + y) pigment { rgb <1, 0.5, 0.2> } translate y * 1.2 }
#declare C = text { ttf "cyrvetic.ttf" concat("n = ", str(int(clock * 10), 0, 0)) 0.1, 0 scale 0.8 }
object { Centred(C, x) pigment { rgb <0.3, 0.6, 1> } translate y * 0.2 }
#declare B = box { <0, 0, 0>, <1, 0.5, 0.5> rotate z * 30 }
object { B translate -min_extent(B) + <1.3, -0.5, -1> pigment { rgb 0.9 } }
sphere { max_extent(T) * <1, 1, 0> + <0, 1.2, 0>, 0.1 pigment { rgb <0, 1, 0> } }
