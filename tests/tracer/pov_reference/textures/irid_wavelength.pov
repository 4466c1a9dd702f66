// irid.pov under global_settings { irid_wavelength <0.25, 0.18, 0.14> }
// (the values POV-Ray's documentation gives as the default; 3.7's own is
// <0.70, 0.52, 0.48>). tests/tracer/pov_reference_test.cpp compares
// hexant's stills with POV-Ray 3.7's (README.md, "Textures").
#version 3.7;
global_settings { assumed_gamma 1.0 irid_wavelength rgb <0.25, 0.18, 0.14> }
camera { location <0, 1, -5> look_at <0, 0.2, 0> angle 55 }
light_source { <-3, 4, -5>, rgb 0.8 }
light_source { <4, 2, -3>, rgb <0.3, 0.3, 0.4> }
plane { y, -0.6 pigment { checker rgb <0.1, 0.2, 0.5> rgb 0.9 } finish { ambient 0.2 } }
sphere { <-1.5, 0.1, 0>, 0.65 pigment { rgb 0.6 }
  finish { ambient 0 diffuse 0.7 phong 0.6 irid { 0.5 thickness 0.3 + 0.4 * clock } } }
sphere { <0, 0.1, 0>, 0.65 pigment { rgb 0.5 }
  finish { ambient 0 diffuse 0.5 irid { 0.7 thickness 0.5 turbulence 0.6 } } }
sphere { <1.5, 0.1, 0>, 0.65 pigment { rgb <0.3, 0.4, 0.3> }
  finish { ambient 0 diffuse 0.4 reflection 0.4 irid { 0.4 thickness 0.8 } } }
