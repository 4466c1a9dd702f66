// #default in every part of a texture, as POV-Ray 3.7 reads it: each new
// texture, and the pigment, normal or finish of an object that has no
// texture yet, starts from a copy of the #default texture as it is at that
// point; a finish { } inside a texture modifies the one it has; a later
// #default changes what follows only. tests/tracer/pov_reference_test.cpp
// compares hexant's stills with POV-Ray 3.7's (README.md, "Textures").
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.2, -5> look_at <0, 0.4, 0> angle 55 }
light_source { <-4, 6, -5>, rgb 1 }
#default { finish { ambient 0.25 + 0.2 * clock diffuse 0.5 phong 0.6 phong_size 20 } }
plane { y, -0.5 pigment { checker rgb <0.2, 0.3, 0.6> rgb 0.9 } }
// a pigment alone: the default finish with it
sphere { <-1.6, 0.2, 0>, 0.6 pigment { rgb <0.9, 0.2, 0.1> } }
// a texture with a finish of its own: the default's other settings kept
sphere { <0, 0.2, 0>, 0.6 texture { pigment { rgb <0.2, 0.8, 0.2> } finish { specular 0.6 phong 0 } } }
// a declared finish starts from the default one
#declare Dull = finish { diffuse 0.9 phong 0 }
#declare T = texture { pigment { rgb <0.9, 0.8, 0.2> } finish { Dull } }
// a finish after a texture modifies the texture's finish
sphere { <1.6, 0.2, 0>, 0.6 texture { T } finish { ambient 0.05 } }
#default { pigment { rgb <0.6, 0.3, 0.8> } normal { bumps 0.6 scale 0.15 } }
// no texture at all: the whole default as it is now (bumps, violet)
box { <-2.2, 1.1, 0.6>, <-1.0, 1.9, 1.0> }
// a pigment over the default's normal
sphere { <0, 1.5, 0.8>, 0.4 pigment { rgb <0.3, 0.8, 0.9> } }
#default { texture { pigment { rgb <0.9, 0.5, 0.2> } finish { ambient 0.4 diffuse 0.3 } } }
// after a later #default: the newest one
box { <1.0, 1.1, 0.6>, <2.2, 1.9, 1.0> }
