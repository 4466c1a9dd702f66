// error: 3:1: pigment pattern 'tiling' (written at
#declare Stone = pigment { tiling 5 }
sphere { 0, 1 pigment { Stone } }
