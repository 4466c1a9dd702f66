// number_of_waves: waves and ripples summing 3 wave sources instead of
// POV-Ray's 10 (global_settings { number_of_waves 3 }): a floor of waves,
// a box of ripples whose phase moves with clock, and a ball with a ripples
// and a waves normal. tests/tracer/pov_reference_test.cpp compares hexant's
// stills with POV-Ray 3.7's.
#version 3.7;
global_settings { assumed_gamma 1.0 number_of_waves 3 }
camera { location <0, 3, -5> look_at <0, 0.3, 0> angle 55 }
light_source { <-3, 6, -4>, rgb 1 }
plane { y, 0 pigment { waves scale 0.3 color_map { [0 rgb <0.1, 0.2, 0.5>] [1 rgb <0.9, 0.9, 0.6>] } } }
box { <-1.8, 0, -0.5>, <-0.6, 1, 0.5>
  pigment { ripples scale 0.2 phase clock color_map { [0 rgb 0.2] [1 rgb <1, 0.6, 0.3>] } } }
sphere { <0.4, 0.6, 0>, 0.6 pigment { rgb 0.8 } normal { ripples 0.8 scale 0.15 } }
sphere { <1.6, 0.5, -0.4>, 0.5 pigment { rgb <0.5, 0.8, 0.5> } normal { waves 0.8 scale 0.15 } }
