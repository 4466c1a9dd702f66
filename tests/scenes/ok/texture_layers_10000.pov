// (issue 45) once: 10,000 texture layers read in quadratic time (2,000 took
// 20 s, 10,000 had not finished at 60 s). Read in linear time now (a layer
// on top is added at the end of Texture::below).
camera { location <0, 0, -5> look_at 0 }
light_source { <5, 5, -5> color rgb 1 }
sphere { 0, 1
#for (I, 1, 10000)
  texture { pigment { rgbf <1, 0.5, 0.2, 0.5> } }
#end
}
