// Reference scene for hexant's interpreter tests: every #debug line is
// NAME = VALUE, floats printed with str(v, 0, 10). See README.md.
#version 3.7;
// Expressions that depend on clock; run at several clocks (see README.md).

#debug concat("clock = ", str((clock), 0, 10), "\n")
#debug concat("clock_sq = ", str((clock * clock), 0, 10), "\n")
#debug concat("sin_turn = ", str((sin(clock * 2 * pi)), 0, 10), "\n")
#debug concat("cond_clock = ", str((clock > 0.3 ? 1 : 2), 0, 10), "\n")
#debug concat("select_clock = ", str((select(clock - 0.5, -1, 1)), 0, 10), "\n")
#debug concat("min_clock = ", str((min(clock, 0.5)), 0, 10), "\n")
#debug concat("mod_clock = ", str((mod(clock * 3, 1)), 0, 10), "\n")
#debug concat("int_clock = ", str((int(clock * 3.5)), 0, 10), "\n")
#debug concat("lerp = ", str((10 + (20 - 10) * clock), 0, 10), "\n")
#declare S = spline { natural_spline 0, <0, 0, 0>  0.5, <1, 2, 0>  1, <0, 4, 1> }
#declare R = <clock, 2 * clock, 0>;
#debug concat("position.x = ", str(R.x, 0, 10), "\n")
#debug concat("position.y = ", str(R.y, 0, 10), "\n")
#debug concat("position.z = ", str(R.z, 0, 10), "\n")
#declare R = vrotate(<1, 0, 0>, y * 360 * clock);
#debug concat("turned.x = ", str(R.x, 0, 10), "\n")
#debug concat("turned.y = ", str(R.y, 0, 10), "\n")
#debug concat("turned.z = ", str(R.z, 0, 10), "\n")
#declare R = S(clock);
#debug concat("spline_clock.x = ", str(R.x, 0, 10), "\n")
#debug concat("spline_clock.y = ", str(R.y, 0, 10), "\n")
#debug concat("spline_clock.z = ", str(R.z, 0, 10), "\n")
#declare R = (1 - clock) * <1, 0, 0> + clock * <0, 0, 1>;
#debug concat("colour_fade.x = ", str(R.x, 0, 10), "\n")
#debug concat("colour_fade.y = ", str(R.y, 0, 10), "\n")
#debug concat("colour_fade.z = ", str(R.z, 0, 10), "\n")
// User functions of clock: a body that reads clock, and one called with it.
#declare F_clock = function(a) { a * clock + sin(3 * clock) }
#declare F_plain = function(a, b) { a * a - b }
#debug concat("function_clock = ", str(F_clock(2), 0, 10), "\n")
#debug concat("function_of_clock = ", str(F_plain(clock, 0.5 * clock), 0, 10), "\n")
