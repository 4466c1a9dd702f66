// error: 2:40: expected a warp in warp { }
sphere { 0, 1 pigment { checker warp { spiral } } }
