// hexant against POV-Ray 3.7: image_map on each map type (planar tiled
// and once, spherical, cylindrical, torus), each interpolation, alpha,
// filter all and transmit all, a PNG with a gAMA chunk, the images moving
// and turning with clock. (The see-through objects cast no shadow:
// hexant's shadows are opaque, POV-Ray filters them; another issue.)
// tiles.png: 8 x 6 RGBA, its two bottom rows partly clear; gamma18.png:
// 5 x 4 RGB with a gAMA chunk of 1/1.8 (both made by make_images.py).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -6> look_at <0, 0.4, 0> angle 50 }
light_source { <-5, 8, -6> color rgb 1 }
light_source { <4, 3, -5> color rgb 0.3 }
background { rgb <0.1, 0.1, 0.2> }
// The floor: tiled, bilinear.
plane { y, -1
  pigment { image_map { png "tiles.png" interpolate 2 } rotate x * 90 scale 1.5 translate x * clock }
}
// Planar, once, over a checker showing through its alpha and outside it.
box { <-3.2, -0.95, 1.5>, <-1.2, 1, 1.6>
  texture { pigment { checker rgb 1, rgb 0.2 scale 0.25 } }
  texture { pigment { image_map { "tiles.png" once transmit all 0.2 } scale 1.5 translate <-3, -0.8, 0> } }
  no_shadow
}
// Spherical, normalized distance.
sphere { <-1, 0.2, 0>, 0.9
  pigment { image_map { png "tiles.png" map_type 1 interpolate 4 } rotate y * 90 * clock }
}
// Cylindrical, bicubic, with filter all.
cylinder { <1.2, -0.95, 0>, <1.2, 1.2, 0>, 0.7
  pigment { image_map { png "gamma18.png" map_type 2 interpolate 3 filter all 0.3 } scale <1, 2.2, 1> translate <1.2, -1, 0> }
  no_shadow
}
// Torus map, no interpolation.
torus { 0.6, 0.25
  pigment { image_map { png "tiles.png" map_type 5 } scale <1, 1, 1> }
  rotate x * -60 translate <2.6, 0.4, -0.8>
}
