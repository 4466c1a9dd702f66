// error: 2:14: at least one key
#declare S = spline { linear_spline }

