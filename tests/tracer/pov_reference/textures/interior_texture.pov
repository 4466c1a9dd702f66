// hexant against POV-Ray 3.7: interior_texture { } (POV-Ray's
// Interior_Texture), the texture a ray meeting the surface from inside
// sees: a sphere opened by clipped_by (the interior texture layered, with
// a bumpy normal), one seen through its partly clear outer texture, a
// union handing its interior texture to a member without one, and an
// interior texture moved with the object as it turns with clock.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.3, 0> angle 50 }
light_source { <-5, 8, -6> color rgb 1 }
light_source { <6, 3, -4> color rgb 0.4 }
plane { y, -1 pigment { rgb 0.7 } }
sphere { <-1.6, 0.2, 0>, 0.9
  texture { pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }
  interior_texture { pigment { rgb <0.2, 0.8, 0.3> } }
  interior_texture { pigment { checker rgbt 1 rgb <1, 1, 0.5> scale 0.2 } normal { bumps 0.6 scale 0.1 } }
  clipped_by { plane { y, 0.5 } }
  rotate z * 30 * clock
}
sphere { <0.3, 0.2, 0>, 0.9
  texture {
    pigment { gradient y color_map { [0.5 rgb <0.2, 0.3, 0.9>] [0.5 rgbt 1] } scale 0.5 }
  }
  interior_texture { pigment { rgb <1, 0.8, 0.1> } finish { ambient 0.3 } }
}
union {
  box { <-0.5, -0.5, -0.5>, <0.5, 0.5, 0.5> }
  sphere { <0, 0.3, 0>, 0.45 texture { pigment { rgb 1 } } }
  texture { pigment { rgb <0.3, 0.5, 1> } }
  interior_texture { pigment { onion color_map { [0 rgb <1, 0.2, 0.6>] [1 rgb <0.2, 1, 1>] } scale 0.2 } }
  clipped_by { box { <-0.4, -0.6, -0.6>, <0.6, 0.6, 0.4> inverse } }
  rotate y * (20 + 30 * clock)
  translate <2, -0.3, 0>
}
