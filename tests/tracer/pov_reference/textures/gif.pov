// GIF and POT files as POV-Ray 3.7 reads them: a GIF image_map (its
// transparent index clear), a height_field from a GIF (its heights the
// palette indices times 256) and one from a POT file (Fractint's 16-bit
// GIF: high bytes on the left half, low bytes on the right), moving with
// clock; the POT field is smooth under a scale that is not uniform (POV-Ray
// blends the corners' normals after taking them to the world).
// indexed.gif and heights.pot are made by make_gifs.py
// (pov_reference/README.md).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -5> look_at <0, 0.2, 0> angle 55 }
light_source { <-3, 8, -6> rgb 1 }
background { rgb <0.1, 0.1, 0.3> }
box { <0, 0, 0>, <1, 1, 0.05>
  pigment { image_map { gif "indexed.gif" } }
  finish { ambient 0.6 diffuse 0.4 }
  translate <-0.5, -0.5, 0> scale <2.4, 1.6, 1> rotate x * -20
  translate <-1.2 + 0.5 * clock, 1.0, 1.5> }
height_field { gif "indexed.gif"
  translate <-0.5, 0, -0.5> scale <1.8, 0.5, 1.8> rotate y * 40 * clock
  pigment { rgb <0.4, 0.6, 0.9> } translate <1.4, -0.8, -0.6> }
height_field { pot "heights.pot" smooth
  translate <-0.5, 0, -0.5> scale <2, 0.8 + 0.4 * clock, 2>
  pigment { rgb <0.8, 0.7, 0.5> } translate <-1, -0.8, -0.6> }
