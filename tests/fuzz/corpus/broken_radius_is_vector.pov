// error: 2:10: radius must be a float
sphere { 0, <1, 2, 3> }

