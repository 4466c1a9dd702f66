// hexant against POV-Ray 3.7: textures that blend whole textures
// (texture_map, a checker's two textures) and layered textures, with
// their patterns, phases and transforms moving with clock.
camera { location <0, 1.5, -5> look_at <0, 0.3, 0> angle 45 }
light_source { <-5, 8, -6> color rgb 1 }
light_source { <6, 3, -4> color rgb 0.4 }
#declare Rough = texture {
  pigment { color rgb <0.8, 0.3, 0.2> }
  normal { bumps 0.6 scale 0.1 }
  finish { phong 0.5 }
}
// A checker of two textures, one reflecting.
plane { y, -1
  texture {
    checker
      texture { pigment { rgb 0.9 } }
      texture { pigment { rgb <0.2, 0.3, 0.6> } finish { reflection 0.3 } }
    scale 0.5
  }
}
// A texture_map: a declared texture with a bumpy normal and one written in
// place, blended by a gradient whose phase moves and which turbulence warps.
sphere { <-1.1, 0.2, 0>, 0.9
  texture {
    gradient y
    texture_map {
      [0.3 Rough]
      [0.7 pigment { color rgb <0.2, 0.7, 0.3> } finish { specular 0.6 roughness 0.01 }]
    }
    scale 0.6 phase clock turbulence 0.3
  }
}
// Layers: a partly clear bozo over wood, turning with the ball.
sphere { <1.1, 0.2, 0>, 0.9
  texture { pigment { wood color_map { [0 rgb <0.6, 0.4, 0.2>] [1 rgb <0.3, 0.15, 0.05>] } scale 0.2 } }
  texture {
    pigment { bozo color_map { [0.4 rgbt <1, 1, 1, 1>] [0.6 rgbf <0.2, 0.5, 1, 0.5>] } scale 0.3 }
    finish { phong 0.8 }
  }
  rotate y * 60 * clock
}
// hexant against POV-Ray 3.7: normals that blend whole normals (normal_map,
// a checker's two normals), a slope_map shaping a pattern's slope, and a
// normal_map inside a texture_map's entry, with phases, amounts and
// transforms moving with clock.
camera { location <0, 2, -5> look_at <0, 0, 0> angle 45 }
light_source { <-5, 8, -6> color rgb 1 }
light_source { <5, 2, -3> color rgb 0.3 }
// A checker of two normals on the floor.
plane { y, -1
  pigment { rgb 0.8 }
  normal { checker normal { bumps 0.8 scale 0.05 }, normal { waves 0.6 + 0.4 * clock scale 0.2 } scale 0.7 }
  finish { phong 0.6 }
}
// A normal_map: dents and ripples blended by a gradient whose phase moves.
sphere { <-1.2, 0, 0>, 0.9
  pigment { rgb <0.9, 0.6, 0.3> }
  normal {
    gradient x
    normal_map {
      [0.3 dents 0.9 scale 0.2]
      [0.7 ripples 1 frequency 2 scale 0.5]
    }
    phase 0.5 * clock scale 0.8 rotate z * 30
  }
  finish { phong 0.8 phong_size 60 }
}
// A slope_map: a gradient's slope shaped into round ridges; and a
// texture_map whose entry has a normal_map of its own.
sphere { <1.2, 0, 0>, 0.9
  texture {
    onion
    texture_map {
      [0.4 pigment { rgb <0.3, 0.6, 0.9> }
           normal { marble 0.7 slope_map { [0 <0, 1>] [0.5 <1, 0>] [1 <0, -1>] } scale 0.3 }
           finish { specular 0.5 }]
      [0.6 pigment { rgb <0.9, 0.9, 0.5> }
           normal { spotted normal_map { [0 wrinkles 0.8 scale 0.3] [1 quilted 1 scale 0.2] } }]
    }
    scale 0.5 translate x * clock
  }
}
#declare Glass = texture { pigment { rgbf <0.9, 0.95, 1, 0.8> } finish { reflection 0.1 phong 0.9 } }
  texture { pigment { gradient y color_map { [0.5 rgbt 1] [0.5 rgbf <1, 0.2, 0.1, 0.4>] } scale 0.4 + 0.2 * clock } 
            normal { ripples 0.5 scale 0.3 } }
sphere { <-1.4, 0, 0>, 0.9 texture { Glass } interior { ior 1.3 } no_shadow }
sphere { <0.2, 0, 0.5>, 0.9
  texture {
    marble
    texture_map {
      [0.2 Glass]
      [0.8 pigment { rgb <0.3, 0.8, 0.4> } finish { phong 1 } ]
    }
    turbulence 0.5 scale 0.5 rotate z * 90 * clock
  }
  interior { ior 1.1 } no_shadow
}
box { <-0.6, -1, -0.6>, <0.6, 0.2, 0.6>
  material {
    texture { pigment { rgb <0.7, 0.6, 0.5> } finish { specular 0.4 } }
    texture { pigment { spotted color_map { [0.5 rgbt 1] [0.5 rgb <0.1, 0.1, 0.5>] } scale 0.2 } }
  }
  pigment { rgbt <1, 1, 1, 0.3> }
  rotate y * 30 translate <1.6, 0, -0.8> no_shadow
}
