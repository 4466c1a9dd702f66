// error: 3:46: the repeat warp's direction is zero
#declare Axis = <0, 0, 0>;
plane { z, 0 pigment { checker warp { repeat Axis offset y } } }
