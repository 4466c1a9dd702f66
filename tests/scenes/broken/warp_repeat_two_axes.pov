// error: 2:46: the repeat warp's direction has more than one non-zero component
plane { z, 0 pigment { checker warp { repeat <1, 1, 0> } } }
