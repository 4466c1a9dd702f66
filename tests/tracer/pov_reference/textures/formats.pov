// The image formats hexant reads through OpenImageIO as POV-Ray 3.7 reads
// them: the same colours as image_maps in JPEG, Targa (run-length; its type
// told by the word), PPM and BMP (told by the name), TIFF and Radiance HDR
// (linear, up to 3), each decoded with POV-Ray's default for its format
// (sRGB for JPEG, Targa and BMP; the values as they are for PPM and TIFF;
// linear for HDR), and a 16-bit PGM as a height_field. The files are made
// by oiiotool (pov_reference/README.md).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x * 4 up y * 3 }
light_source { <-3, 8, -10> rgb 1 }
background { rgb 0.1 }
#declare Tile = finish { ambient 1 diffuse 0 }
box { <0, 0, 0>, <1, 1, 0.05> pigment { image_map { jpeg "colours.jpg" } } finish { Tile }
  translate <-0.5, -0.5, 0> scale <1.2, 0.8, 1> translate <-1.3, 1.05, 0> }
box { <0, 0, 0>, <1, 1, 0.05> pigment { image_map { tga "colours.tga" } } finish { Tile }
  translate <-0.5, -0.5, 0> scale <1.2, 0.8, 1> translate <0, 1.05, 0> }
box { <0, 0, 0>, <1, 1, 0.05> pigment { image_map { "colours.ppm" } } finish { Tile }
  translate <-0.5, -0.5, 0> scale <1.2, 0.8, 1> translate <1.3, 1.05, 0> }
box { <0, 0, 0>, <1, 1, 0.05> pigment { image_map { "colours.bmp" } } finish { Tile }
  translate <-0.5, -0.5, 0> scale <1.2, 0.8, 1> translate <-1.3, 0.15, 0> }
box { <0, 0, 0>, <1, 1, 0.05> pigment { image_map { tiff "colours.tif" } } finish { Tile }
  translate <-0.5, -0.5, 0> scale <1.2, 0.8, 1> translate <0, 0.15, 0> }
box { <0, 0, 0>, <1, 1, 0.05> pigment { image_map { hdr "glow.hdr" } } finish { Tile }
  translate <-0.5, -0.5, 0> scale <1.2, 0.8, 1> translate <1.3, 0.15, 0> }
height_field { pgm "heights16.pgm" smooth
  translate <-0.5, 0, -0.5> scale <3.6, 0.6, 2>
  rotate x * -60 translate <0, -1.45, -1>
  pigment { rgb <0.8, 0.7, 0.5> } }
