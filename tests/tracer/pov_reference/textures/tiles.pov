// hexant against POV-Ray 3.7: tiles { } (POV-Ray's Parse_Tiles), a checker
// of two textures in its old order: the first tile's where the checker is
// 1, tile2's where 0. A first tile of two layers, a tile2 that reflects,
// transforms after the block moving with clock, tiles in a texture_map's
// entry, a tile of a declared texture.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -5> look_at <0, 0.2, 0> angle 50 }
light_source { <-5, 8, -6> color rgb 1 }
light_source { <6, 3, -4> color rgb 0.4 }
#declare Plain = texture { pigment { rgb <0.9, 0.2, 0.2> } }
plane { y, -1
  texture {
    tiles {
      texture { pigment { wood color_map { [0 rgb <0.6, 0.4, 0.2>] [1 rgb <0.3, 0.15, 0.05>] } scale 0.1 } }
      texture { pigment { bozo color_map { [0.5 rgbt 1] [0.6 rgb <0.2, 0.5, 1>] } scale 0.2 } }
      tile2
      texture { pigment { rgb 0.8 } finish { reflection 0.3 phong 0.6 } }
    }
    scale 0.7 rotate y * 40 * clock
  }
}
sphere { <-1.2, 0.2, 0>, 0.9
  texture {
    tiles {
      texture { pigment { rgb <0.1, 0.6, 0.2> } normal { bumps 0.5 scale 0.05 } }
      tile2 texture { Plain }
    }
    scale 0.4 translate <0.2 * clock, 0, 0>
  }
}
sphere { <1.2, 0.2, 0>, 0.9
  texture {
    gradient y
    texture_map {
      [0.4 pigment { rgb <1, 0.9, 0.3> }]
      [0.6 tiles { texture { pigment { rgb <0.2, 0.2, 0.7> } } tile2 texture { pigment { rgb 1 } } } scale 0.25]
    }
    scale 1.2 translate -0.5 * y
  }
}
