// error: 3:1: pigment pattern 'cells' (written at
#declare Stone = pigment { cells }
sphere { 0, 1 pigment { Stone } }
