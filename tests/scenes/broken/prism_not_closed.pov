// error: 2:26: Too few points in prism.
prism { quadratic_spline 0, 1, 6, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0, 0>, <-1, 0> }
