#declare S = concat("t", str(clock, 0, 1));
text { ttf "timrom.ttf" S, 0.2 + 0.1 * clock, <0.01, 0, 0> pigment { rgb 1 } rotate y * 20 }
text { ttf "cyrvetic.ttf" "AV Wa", -0.1, 0 translate y }
camera { location <0.5, 0.3, -3> look_at <0.5, 0.3, 0> }
light_source { <2, 3, -4> rgb 1 }
