// metallic: highlights (phong, specular) and a reflection { metallic }
// tinted by the pigment through POV-Ray's empirical Fresnel curve, with the
// amount written, left to its 1, and moving with clock.
// tests/tracer/pov_reference_test.cpp compares hexant's stills with POV-Ray
// 3.7's (README.md, "Textures").
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5> look_at <0, 0.3, 0> angle 55 }
light_source { <-3, 5, -6>, rgb 1 }
light_source { <4, 2, -3>, rgb <0.5, 0.5, 0.6> }
plane { y, -0.5 pigment { checker rgb <0.1, 0.2, 0.5> rgb 0.9 } finish { ambient 0.2 } }
sphere { <-1.6, 0.3, 0>, 0.7 pigment { rgb <0.9, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.4 phong 1 phong_size 30 metallic } }
sphere { <0, 0.3, 0>, 0.7 pigment { rgb <0.9, 0.7, 0.2> }
  finish { ambient 0.1 diffuse 0.3 specular 0.9 roughness 0.02 metallic 0.4 + 0.6 * clock
           reflection { 0.5 metallic } } }
sphere { <1.6, 0.3, 0>, 0.7 pigment { rgb <0.3, 0.9, 0.4> }
  finish { ambient 0.1 diffuse 0.5 phong 0.8 reflection { 0.3 metallic 0.7 } } }
