// hexant against POV-Ray 3.7: layered textures in depth. A declared
// layered texture whose top lets the lower layers and what lies behind show
// (filter and transmit, refracting through every layer), each layer with
// its own finish, normal and reflection; a texture_map whose entries are
// layered; textures layered in a material and in an object's modifiers.
// (The see-through objects cast no shadow: hexant's shadows are opaque,
// POV-Ray filters them; another issue.)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.2, -5> look_at <0, 0.2, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, -1 pigment { checker rgb 1, rgb <0.3, 0.3, 0.4> } }
plane { z, 4 pigment { gradient x color_map { [0 rgb <1, 0.8, 0.2>] [1 rgb <0.2, 0.4, 1>] } } }
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
