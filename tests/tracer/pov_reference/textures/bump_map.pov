// hexant against POV-Ray 3.7: normal { bump_map { } }: a palette PNG's
// indices as heights (use_index, bilinear) on a wall sliding with clock,
// an RGBA PNG's greys (use_colour, the default) on a turning sphere
// (spherical, bicubic) and on the floor (tiled, scaled by bump_size), the
// images read undecoded as POV-Ray reads a height_field's. palette.png
// and tiles.png are make_images.py's.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.3, 0> angle 50 }
light_source { <-5, 8, -6> color rgb 1 }
light_source { <4, 3, -5> color rgb 0.4 }
background { rgb <0.1, 0.1, 0.2> }
plane { y, -1
  pigment { rgb <0.8, 0.7, 0.5> }
  normal { bump_map { png "tiles.png" bump_size 2 } rotate x * 90 scale 1.5 }
}
box { <-3, -1, 1>, <3, 2, 1.1>
  pigment { rgb 0.8 }
  finish { phong 0.6 }
  normal { bump_map { png "palette.png" use_index interpolate 2 bump_size 0.15 }
           scale <6, 3, 1> translate <-3, -1, 0> translate x * clock }
}
sphere { <0.8, 0.2, 0>, 0.9
  pigment { rgb <0.9, 0.5, 0.4> }
  finish { phong 0.8 }
  normal { bump_map { "tiles.png" map_type 1 interpolate 3 use_colour bump_size 4 } rotate y * 90 * clock }
}
sphere { <-1.3, 0.1, -0.5>, 0.6
  pigment { rgb <0.4, 0.6, 0.9> }
  normal { bump_map { png "palette.png" once } scale 0.8 translate <-1.7, -0.3, 0> }
}
