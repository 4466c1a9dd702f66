// flags: --frame-count 8
// clock is symbolic: each of these is a function of time, not a number.
#declare Path = spline { natural_spline 0, <0, 0, 0> 0.5, <1, 2, 0> 1, <0, 4, 1> }
#declare Orbit = vrotate(3 * x, 360 * clock * z);
sphere { Orbit, 0.5 }
sphere { Path(clock), 0.2 + 0.1 * sin(2 * pi * clock) }
cylinder { <0, 0, 0>, <0, 1 + clock, 0>, 0.1 }
box { -1, 1 rotate y * 360 * 10 * clock }            // ten turns over the animation
box { -1, 1 twist y, 90 * clock taper y, 0.5 bend x, 30 * clock }
sphere { 0, 1 pigment { rgb <clock, 0, 1 - clock> } }
camera { location <0, 2, -10> + x * clock look_at 0 }
light_source { <10, 10, -10> * (1 + clock), rgb 1 }
// MegaPOV's motion_blur { } reads as a plain group: the blur is hexant's anyway.
motion_blur { sphere { x * clock, 0.3 } }
// Strings on clock: a counter's digits and a label, piecewise in time.
#declare Label = concat("frame ", str(frame_number, -3, 0), " at ", str(clock, 0, 1));
#if (strlen(Label) > 15 & strcmp(substr(Label, 7, 3), "004") >= 0)
  sphere { <0, 3, 0>, 0.2 }
#end
#declare Code = chr(asc("A") + int(clock * 4));
#debug concat(Code, "\n")
