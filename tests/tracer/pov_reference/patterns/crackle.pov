// crackle: POV-Ray's cells around a random point in each unit cube (its
// PatternRands table, Boost's mt19937), with the default form and metric,
// a metric of 1 with form, offset and turbulence, a metric of 3, cells
// (a random value a cube, from the same table), and solid crackle (each
// cell the noise at its point) moving with clock; phase moving with clock. tests/tracer/pov_reference_test.cpp compares hexant's
// stills with POV-Ray 3.7's (README.md, "Patterns").
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -4> look_at 0 angle 60 }
plane { z, 1 pigment { crackle scale 0.5 phase 0.3 * clock } finish { ambient 1 diffuse 0 } }
sphere { <1, 0, -1>, 0.7 pigment { crackle metric 1 form <1, -0.5, 0.2> offset 0.3 scale 0.3 turbulence 0.2 color_map { [0 rgb <1, 0.5, 0>] [1 rgb <0, 0.2, 1>] } } finish { ambient 1 diffuse 0 } }
sphere { <-1.2, -0.5, -1>, 0.6 pigment { crackle metric 3 scale 0.25 } finish { ambient 1 diffuse 0 } }
box { <-2.2, 0.6, -0.5>, <-0.8, 1.4, 0.5> pigment { cells scale 0.2 } finish { ambient 1 diffuse 0 } }
box { <0.6, 0.7, -0.5>, <2.2, 1.5, 0.5> pigment { crackle solid scale 0.25 translate x * clock color_map { [0 rgb <0.2, 0.1, 0>] [1 rgb <1, 0.9, 0.6>] } } finish { ambient 1 diffuse 0 } }
