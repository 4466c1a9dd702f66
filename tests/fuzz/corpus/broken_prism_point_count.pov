// error: 2:36: says it has 4 points but lists 3
prism { linear_sweep linear_spline 0, 1, 4, <0, 0>, <1, 0>, <0, 1> }

