// hexant against POV-Ray 3.7: textures that blend whole textures
// (texture_map, a checker's two textures) and layered textures, with
// their patterns, phases and transforms moving with clock; and a block
// pattern's list of pigments.
#version 3.7;
global_settings { assumed_gamma 1.0 }
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
// A block pattern's list of pigments (the third of hexagon's left out: its
// default colour), one a pattern of its own moving with clock.
box { <-2.5, -1, 1.5>, <2.5, 1.5, 1.6>
  pigment { hexagon pigment { bozo scale 0.2 phase clock } pigment { rgb <1, 0.9, 0.6> } scale 0.3 }
}
