// triangular: POV-Ray's six-colour tiling of equilateral triangles, with its
// default colours, six of its own (one fading with clock) turned and moved
// with clock, and under turbulence. tests/tracer/pov_reference_test.cpp
// compares hexant's stills with POV-Ray 3.7's (README.md, "Patterns").
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -5> look_at <0, 0, 0.5> angle 60 }
plane { y, 0 pigment { triangular scale 0.5 translate <0.3 * clock, 0, 0> } finish { ambient 1 diffuse 0 } }
box { <-2.5, 0.01, 1>, <-0.2, 0.02, 3>
  pigment { triangular rgb <1, 1, 1> rgb <0.2, 0.2, 0.2> rgb <1, 0.5, 0> rgb <0, 0.5, 1>
            rgb <0.5, 0, 0.5> rgb <0.6 * clock, 0.8, 0.3> scale 0.3 rotate y * 30 * clock }
  finish { ambient 1 diffuse 0 } }
box { <0.2, 0.01, 1>, <2.5, 0.02, 3>
  pigment { triangular scale 0.25 turbulence 0.3 } finish { ambient 1 diffuse 0 } }
