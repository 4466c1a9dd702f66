// error: 3:1: pigment pattern 'crackle' (written at
#declare Stone = pigment { crackle }
sphere { 0, 1 pigment { Stone } }
