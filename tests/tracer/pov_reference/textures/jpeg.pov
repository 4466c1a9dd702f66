// JPEG files as POV-Ray 3.7 reads them: an image_map (its type told by the
// word and by the name's extension alone), a height_field from a gray JPEG
// and one from a colour JPEG (its height red * 256 + green, as POV-Ray
// reads a colour image), moving with clock. colours.jpg and heights.jpg
// are made by oiiotool (pov_reference/README.md).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -5> look_at <0, 0.2, 0> angle 55 }
light_source { <-3, 8, -6> rgb 1 }
background { rgb 0.1 }
box { <0, 0, 0>, <1, 1, 0.05>
  pigment { image_map { jpeg "colours.jpg" } }
  finish { ambient 0.6 diffuse 0.4 }
  translate <-0.5, -0.5, 0> scale <2.4, 1.8, 1> rotate x * -20
  translate <-1.4 + 0.5 * clock, 0.9, 1.5> }
box { <0, 0, 0>, <1, 1, 0.05>
  pigment { image_map { "colours.jpg" interpolate 2 } }
  finish { ambient 0.6 diffuse 0.4 }
  translate <-0.5, -0.5, 0> scale <1.6, 1.2, 1> rotate y * (20 + 30 * clock)
  translate <1.6, 1.1, 1.2> }
height_field { "heights.jpg" smooth
  translate <-0.5, 0, -0.5> scale <2, 0.8 + 0.4 * clock, 2>
  pigment { rgb <0.8, 0.7, 0.5> } translate <-1, -0.8, -0.6> }
height_field { jpeg "colours.jpg"
  translate <-0.5, 0, -0.5> scale <1.8, 0.5, 1.8> rotate y * 40 * clock
  pigment { rgb <0.4, 0.6, 0.9> } translate <1.3, -0.8, -0.8> }
