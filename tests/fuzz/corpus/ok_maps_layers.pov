// Fuzz seed: maps of every kind (pigment_map, normal_map, texture_map,
// material_map, slope_map), layered textures and a checker of textures.
camera { location <0, 1, -4> look_at 0 }
light_source { <-3, 5, -4> rgb 1 }
#declare P = pigment { gradient x pigment_map { [0 checker rgb 1 rgb 0 scale 0.2] [0.5 rgb y] [1 bozo color_map { [0 rgb 0] [1 rgb x] }] } }
#declare N = normal { bozo normal_map { [0 bumps 0.5 scale 0.1] [0.6 dents 2] [1 wrinkles] } }
#declare T = texture { pigment { P } normal { N } finish { phong 0.5 } }
sphere { <-1, 0, 0>, 0.8
  texture { gradient y texture_map { [0 T] [0.5 pigment { rgb <0, 0, 1> }] [1 T scale 2] } phase clock }
}
sphere { <1, 0, 0>, 0.8
  texture { pigment { wood color_map { [0 rgb <0.6, 0.4, 0.2>] [1 rgb 0.1] } } }
  texture { pigment { bozo color_map { [0.4 rgbt 1] [0.6 rgbf <0.2, 0.5, 1, 0.5>] } scale 0.3 } finish { specular 0.4 } }
  normal { gradient x slope_map { [0 <0, 1>] [0.5 <1, 0>] [1 <0, -1>] } }
}
box { <-2, -1.5, -1>, <2, -1, 1>
  texture { material_map { png "test.png" texture { pigment { rgb 1 } } texture { pigment { rgb x } } texture { T } } scale 0.5 }
}
plane { y, -1.5 texture { checker texture { T } texture { pigment { average pigment_map { [1 rgb 1] [2 P] } } } } }
