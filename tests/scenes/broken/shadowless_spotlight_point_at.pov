// error: 2:54: needs a spotlight or cylinder light
light_source { <0, 5, 0>, rgb 1 spotlight shadowless point_at 0 }
