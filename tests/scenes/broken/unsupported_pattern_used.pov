// error: 3:1: pigment pattern 'julia' (written at
#declare Stone = pigment { julia }
sphere { 0, 1 pigment { Stone } }
