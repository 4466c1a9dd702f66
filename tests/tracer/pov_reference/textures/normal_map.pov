// hexant against POV-Ray 3.7: normals that blend whole normals (normal_map,
// a checker's two normals), a slope_map shaping a pattern's slope, and a
// normal_map inside a texture_map's entry, with phases, amounts and
// transforms moving with clock.
#version 3.7;
global_settings { assumed_gamma 1.0 }
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
