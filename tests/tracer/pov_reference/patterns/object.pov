// object: POV-Ray's object pattern, 1 inside its object and 0 outside (a
// blend list of two): colours on a floor from a union of spheres, the
// first colour left to its default; textures on a box from a declared
// cylinder turned by clock; pigments on a ball from a box given as a
// block; a normal from a torus. tests/tracer/pov_reference_test.cpp
// compares hexant's stills with POV-Ray 3.7's.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -5> look_at <0, 0.3, 0> angle 55 }
light_source { <-3, 6, -4>, rgb 1 }
#declare Spots = union { sphere { <-1, 0, 0>, 0.8 } sphere { <1.2, 0, 0.5>, 0.6 } }
plane { y, 0 pigment { object { Spots rgb <0.9, 0.8, 0.2> } } finish { ambient 0.3 diffuse 0.7 } }
#declare Bar = cylinder { -x, x, 0.2 rotate 90 * clock * y translate y * 0.25 }
box { <-0.8, 0, -0.8>, <0.8, 0.6, 0.8>
  texture { object { Bar texture { pigment { rgb <0.2, 0.4, 0.9> } },
                         texture { pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.8 } } }
            scale 1.2 }
  translate <-1.3, 0, 0.5> }
sphere { <1.3, 0.7, 0.6>, 0.7
  pigment { object { box { <-0.2, -1, -1>, <0.2, 1, 1> }
                     pigment { checker rgb 1 rgb 0.2 scale 0.2 }
                     pigment { rgb <0.3, 0.8, 0.3> } }
            translate <1.3 + clock * 0.4, 0.7, 0.6> } }
sphere { <0, 0.4, -1.2>, 0.45
  pigment { rgb 0.8 }
  normal { object { torus { 0.38, 0.1 rotate 90 * x } normal { bumps 0.8 scale 0.05 } normal { granite 0.6 scale 0.3 } } translate <0, 0.4, -1.2> } }
