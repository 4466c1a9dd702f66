// error: 4:1: expected '}'
sphere { <0, 0, 0>, 1
  pigment { rgb 1 }

