// error: 3:1: pigment pattern 'marble' (written at
#declare Stone = pigment { marble }
sphere { 0, 1 pigment { Stone } }

