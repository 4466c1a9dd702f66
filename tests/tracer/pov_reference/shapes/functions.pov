// functions: shapes made from functions.inc's noise and from functions of
// x and y, against POV-Ray 3.7: an isosurface whose surface is
// f_noise3d (POV-Ray's Noise with the scene's generator, fnintern.cpp) and
// moves with clock, one of f_noise_generator with Perlin's noise (3),
// height fields of a float function and of a pigment function (POV-Ray's
// Make_Pattern_Image and image_height_at), and a floor coloured by a
// pattern function (`function { pattern { } }`, POV-Ray's f_pattern). The
// isosurfaces' max_gradient is raised so that POV-Ray's own search finds
// their surfaces (at its default 1.1 it misses some, where hexant's
// interval search does not). The kinds are runtime/texture/pattern/
// noise_function.hpp, runtime/objects/height_field/height_field_function.hpp
// and runtime/texture/pigment_function.hpp; tests/tracer/
// pov_reference_test.cpp compares hexant's stills with POV-Ray 3.7's.
#version 3.7;
global_settings { assumed_gamma 1.0 }
// (functions.inc's declarations of the three, so that the test needs no
// POV-Ray include folder.)
#declare f_sphere = function { internal(61) }
#declare f_noise3d = function { internal(76) }
#declare f_noise_generator = function { internal(78) }
camera { location <0, 3, -4.5> look_at <0, 0, 0.5> angle 55 }
light_source { <-3, 6, -5>, rgb 1 }
#declare Bozo = function { pattern { bozo scale 0.4 } }
plane { y, 0
  pigment { function { Bozo(x, y, z) } color_map { [0 rgb <0.2, 0.3, 0.1>] [1 rgb <0.9, 0.8, 0.6>] } }
  finish { ambient 0.6 diffuse 0.4 } }
isosurface {
  function { f_sphere(x, y, z, 0.6) - f_noise3d(x * 4, y * 4, z * 4) * 0.3 }
  contained_by { sphere { 0, 1 } }
  max_gradient 4
  pigment { rgb <0.9, 0.5, 0.3> }
  translate <-1.2, 0.8, 1 + clock * 0.5> }
isosurface {
  function { f_sphere(x, y, z, 0.5) - f_noise_generator(x * 3, y * 3, z * 3, 3) * 0.3 }
  contained_by { box { -1, 1 } }
  max_gradient 4
  pigment { rgb <0.4, 0.6, 0.9> }
  translate <1.2, 0.8, 1> }
height_field {
  function 48, 40 { 0.5 + 0.5 * sin(x * 9) * cos(y * 7) }
  scale <1, 0.3, 1> translate <-1.3, 0, -1.4>
  pigment { rgb <0.7, 0.9, 0.6> } }
height_field {
  function 40, 32 { pigment { checker color rgb 1 color rgb 0.3 scale 1/4 } }
  scale <1, 0.25, 1> translate <0.3, 0, -1.4>
  pigment { rgb <0.9, 0.9, 0.5> } }
