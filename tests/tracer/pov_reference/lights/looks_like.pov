// looks_like: the object drawn where the light is, moved with it by the
// light's transforms, casting no shadow (the light shines through it).
// tests/tracer/pov_reference_test.cpp compares hexant's stills with
// POV-Ray 3.7's (README.md, "Lights").
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 1, 0> angle 50 }
light_source { <0, 2, 0>, rgb <1, 0.9, 0.7>
    looks_like { sphere { 0, 0.3 pigment { rgb <1, 0.9, 0.6> } finish { ambient 1 diffuse 0 } } }
    translate <-1.5 + 3 * clock, 0, 0> }
light_source { <0, 0, 0>, rgb 0.4
    looks_like { box { -0.2, 0.2 pigment { rgb <0.3, 0.5, 1> } finish { ambient 0.8 } } }
    translate <2, 3, 1> rotate y * 60 * clock }
light_source { <-3, 6, -4>, rgb 0.3 }
background { rgb <0.1, 0.1, 0.15> }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.5 } }
sphere { <0.5, 0.6, -0.5>, 0.6 pigment { rgb <0.8, 0.3, 0.3> } }
