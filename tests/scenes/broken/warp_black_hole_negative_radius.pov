// error: 2:61: the black hole's radius must not be negative
plane { z, 0 pigment { checker warp { black_hole <0, 0, 0>, -0.5 strength 2 } } }
