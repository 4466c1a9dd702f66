// error: 2:50: the warp's orientation must not be <0, 0, 0>
sphere { 0, 1 pigment { checker warp { spherical orientation 0 } } }
