// error: 2:22: Prism with cubic splines must have at least six points.
prism { cubic_spline 0, 1, 5, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0, 0> }
