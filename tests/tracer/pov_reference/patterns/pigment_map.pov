// pigment_map: whole pigments blended by a pattern (a declared one, a colour,
// a pattern of their own), each in the outer pattern's warped space; and
// marble's own turbulence with a pigment map. Phase moves with clock.
// tests/tracer/pov_reference_test.cpp compares hexant's stills with
// POV-Ray 3.7's (README.md, "Patterns").
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -4> look_at 0 angle 60 }
#declare P1 = pigment { checker rgb 1, rgb <0.2, 0.2, 0.6> scale 0.2 }
plane { z, 1 pigment { gradient x pigment_map { [0.2 P1] [0.5, rgb <1, 0.5, 0>] [0.8 bozo scale 0.1 turbulence 0.3] } phase 0.5 * clock scale 2 turbulence 0.2 } finish { ambient 1 diffuse 0 } }
sphere { <1, 0, -1>, 0.7 pigment { marble turbulence 0.5 pigment_map { [0 wood color_map { [0 rgb 1] [1 rgb 0] } scale 0.1] [1 rgb <0.1, 0.5, 0.2>] } } finish { ambient 1 diffuse 0 } }
