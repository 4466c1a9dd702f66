// error: 4:15: must be a float
// povray: line 4: Parse Error: Float expected but vector or color expression found.
#declare S = spline { linear_spline 0, <0, 0, 0> 1, <1, 1, 1> }
#declare P = S(<1, 2, 3>);

