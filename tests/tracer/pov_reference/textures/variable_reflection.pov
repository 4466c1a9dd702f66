// Variable reflection: reflection { MIN, MAX } with falloff, with fresnel
// (through the interior's ior, entering and leaving a glass sphere),
// exponent, conserve_energy, the old syntax `reflection V`, and a minimum
// moving with clock. tests/tracer/pov_reference_test.cpp compares hexant's
// stills with POV-Ray 3.7's (README.md, "Textures").
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 }
camera { location <0, 1.6, -5.5> look_at <0, 0.4, 0> angle 60 }
light_source { <-3, 5, -6>, rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.9, 0.8, 0.6>] [1 rgb <0.2, 0.4, 0.9>] } } }
plane { y, -0.5 pigment { checker rgb <0.1, 0.2, 0.5> rgb 0.9 } finish { ambient 0.2 } }
sphere { <-2.1, 0.3, 0>, 0.6 pigment { rgb <0.8, 0.2, 0.1> }
  finish { diffuse 0.4 reflection { 0.05 + 0.2 * clock, 1 falloff 2 } } }
sphere { <-0.7, 0.3, 0>, 0.6 pigment { rgbf <0.9, 1, 0.9, 0.9> }
  finish { diffuse 0.1 reflection { 0, 1 fresnel on } } interior { ior 1.5 } }
sphere { <0.7, 0.3, 0>, 0.6 pigment { rgb <0.2, 0.6, 0.3> }
  finish { diffuse 0.5 reflection { 0.3, 0.8 exponent 0.6 } } }
sphere { <2.1, 0.3, 0>, 0.6 pigment { rgbt <0.3, 0.3, 0.9, 0.7> }
  finish { diffuse 0.3 reflection { 0.2 0.9 } conserve_energy } interior { ior 1.2 } }
box { <-2.6, -0.5, 1.2>, <2.6, 1.6, 1.3> pigment { rgb <0.9, 0.9, 0.8> }
  finish { reflection 0.25 } }
