// A spotlight whose aim, cone and tightness move with clock, a cylinder
// light, a light that fades with distance, and a point light filling in:
// shadows on a floor. tests/tracer/pov_reference_test.cpp compares
// hexant's stills with POV-Ray 3.7's (README.md, "Lights").
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0, 0> angle 50 }
light_source { <0, 6, 0>, rgb 1 spotlight point_at <1 - 2 * clock, 0, 0> radius 12 + 6 * clock falloff 25 tightness 2 }
light_source { <-3, 3, -3>, rgb 0.5 cylinder point_at <0, 0, 0> radius 0.6 falloff 1.2 tightness 1 translate <clock, 0, 0> }
light_source { <3, 2, -3>, rgb <1, 0.8, 0.6> fade_distance 2 + clock fade_power 2 }
light_source { <-4, 5, -5>, rgb 0.15 shadowless }
// shadowless is a type: this spotlight is a plain fill light (POV-Ray)
light_source { <2, 5, 2>, rgb 0.2 spotlight point_at 0 radius 5 falloff 10 shadowless }
plane { y, 0 pigment { checker rgb 0.9, rgb 0.6 } }
sphere { <-0.5, 0.5, 0>, 0.5 pigment { rgb <0.9, 0.4, 0.3> } finish { phong 0.5 } }
box { <0.5, 0, 0.5>, <1.2, 1.2, 1.2> pigment { rgb <0.3, 0.6, 0.9> } }
