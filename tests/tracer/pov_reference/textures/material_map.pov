// material_map as POV-Ray 3.7 renders it: an image picks a whole texture
// at each point. palette.png (12 palette entries, make_images.py) picks
// among 5 textures by its index (indices above 5 taken modulo 5, index 5
// the last texture); tiles.png (RGB) by its red x 255, modulo 3; `once`
// leaves the first texture outside the image; the textures have their
// own patterns and normals, placed by the map's transforms, and one
// plane moves with clock.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.3, 0> angle 55 }
light_source { <-3, 8, -6> rgb 1 }
background { rgb 0.1 }
#declare Five = texture {
  material_map { png "palette.png"
    texture { pigment { rgb <1, 0.2, 0.1> } }
    texture { pigment { checker rgb 1 rgb 0 scale 0.05 } }
    texture { pigment { rgb <0.1, 0.3, 1> } normal { bumps 0.8 scale 0.05 } }
    texture { pigment { rgb <0.2, 0.9, 0.2> } finish { phong 1 } }
    texture { pigment { gradient x color_map { [0 rgb 0] [1 rgb <1, 1, 0>] } scale 0.2 } }
  }
  translate <-0.5, -0.5, 0> scale <2.4, 1.8, 1>
}
box { <-1.2, -0.9, 0>, <1.2, 0.9, 0.05> texture { Five }
  rotate x * -20 translate <-1.2 + 0.4 * clock, 1.0, 1.5> }
box { <-1, -1, 0>, <1, 1, 0.05>
  texture {
    material_map { png "tiles.png" once map_type 0
      texture { pigment { rgb <0.9, 0.9, 0.9> } }
      texture { pigment { rgb <0.9, 0.4, 0.1> } }
      texture { pigment { rgb <0.2, 0.2, 0.8> } finish { ambient 0.5 } }
    }
    scale 1.2 translate <-0.3, -0.4, 0>
  }
  rotate y * 20 translate <1.4, 1.0, 1.2> }
plane { y, -0.6
  texture { material_map { png "palette.png" interpolate 2
    texture { pigment { rgb 0.8 } }
    texture { pigment { rgb <0.6, 0.1, 0.1> } }
  } rotate x * 90 scale 0.7 translate x * clock } }
