// Reference scene for hexant's interpreter tests: every #debug line is
// NAME = VALUE, floats printed with str(v, 0, 10). See README.md.
#version 3.7;
// User functions: parameters named and default (x, y, z), calls inside
// calls, declared floats inside bodies, POV-Ray's float built-ins, and the
// internal functions hexant builds (declared here as functions.inc does).

#declare K = 0.75;
#declare F_line = function(x, xa, ya, xb, yb) { ((yb - ya) / (xb - xa)) * (x - xa) + ya }
#declare F_xyz = function { x * 2 + y * y - z / 4 }
#declare F_nest = function(a, b) { F_xyz(a, b, a + b) * K + F_line(a, 0, 1, 2, 5) }
#declare F_sel = function(a) { select(a, -1, 0, 1) + select(a - 1, 10, 20) }
#declare F_cmp = function(a, b) { (a < b) + 2 * (a >= b) + 4 * (a = b) + 8 * ((a > 0) & (b > 0)) + 16 * ((a > 0) | (b > 0)) }
#declare F_math = function(a) { abs(a) + floor(a) + ceil(a) + int(a) + mod(a, 0.7) + pow(abs(a), 1.5) + exp(a / 4) + sqrt(abs(a)) }
#declare F_trig = function(a) { sin(a) + cos(a) * tan(a / 3) + atan2(a, 2) + asin(a / 4) + acos(a / 5) + atan(a) }
#declare F_hyp = function(a) { sinh(a) + cosh(a) + tanh(a) + asinh(a) + acosh(abs(a) + 1) + atanh(a / 3) }
#declare F_ang = function(a) { degrees(a) + radians(a) + ln(abs(a) + 1) + log(abs(a) + 1) + min(a, 1, -2) + max(a, 1, -2) }

#declare f_ellipsoid = function { internal(17) }
#declare f_heart = function { internal(23) }
#declare f_helix1 = function { internal(25) }
#declare f_helix2 = function { internal(26) }
#declare f_paraboloid = function { internal(45) }
#declare f_ph = function { internal(47) }
#declare f_pillow = function { internal(48) }
#declare f_r = function { internal(57) }
#declare f_rounded_box = function { internal(60) }
#declare f_sphere = function { internal(61) }
#declare f_superellipsoid = function { internal(68) }
#declare f_th = function { internal(69) }
#declare f_torus = function { internal(70) }
#declare f_torus2 = function { internal(71) }
#declare F_uses_internal = function { f_sphere(x, y, z, 0.5) * 2 - f_torus(y, x, z, 1, 0.25) }

#debug concat("line = ", str(F_line(0.5, 0, 1, 2, 5), 0, 10), "\n")
#debug concat("xyz = ", str(F_xyz(1, 2, 3), 0, 10), "\n")
#debug concat("nest = ", str(F_nest(0.3, -1.2), 0, 10), "\n")
#debug concat("sel_neg = ", str(F_sel(-2), 0, 10), "\n")
#debug concat("sel_zero = ", str(F_sel(0), 0, 10), "\n")
#debug concat("sel_pos = ", str(F_sel(3), 0, 10), "\n")
#debug concat("cmp_1 = ", str(F_cmp(1, 2), 0, 10), "\n")
#debug concat("cmp_2 = ", str(F_cmp(2, 2), 0, 10), "\n")
#debug concat("cmp_3 = ", str(F_cmp(-3, 2), 0, 10), "\n")
#debug concat("math_pos = ", str(F_math(2.3), 0, 10), "\n")
#debug concat("math_neg = ", str(F_math(-1.7), 0, 10), "\n")
#debug concat("trig = ", str(F_trig(0.9), 0, 10), "\n")
#debug concat("hyp = ", str(F_hyp(0.6), 0, 10), "\n")
#debug concat("ang = ", str(F_ang(-0.4), 0, 10), "\n")
#debug concat("ellipsoid = ", str(f_ellipsoid(0.3, -0.4, 0.5, 1, 2, 3), 0, 10), "\n")
#debug concat("heart = ", str(f_heart(0.3, 0.2, -0.4, 1.5), 0, 10), "\n")
#debug concat("paraboloid = ", str(f_paraboloid(0.3, 0.2, -0.4, 2), 0, 10), "\n")
#debug concat("paraboloid_clamped = ", str(f_paraboloid(3, -20, 4, 2), 0, 10), "\n")
#debug concat("ph = ", str(f_ph(0.3, -0.2, 0.4), 0, 10), "\n")
#debug concat("pillow = ", str(f_pillow(0.7, 0.2, -0.4, 1.5), 0, 10), "\n")
#debug concat("r = ", str(f_r(0.3, -0.2, 0.4), 0, 10), "\n")
#debug concat("rounded_box_in = ", str(f_rounded_box(0.1, 0.2, -0.3, 0.1, 1, 0.5, 0.4), 0, 10), "\n")
#debug concat("rounded_box_out = ", str(f_rounded_box(1.3, -0.9, 0.45, 0.1, 1, 0.5, 0.4), 0, 10), "\n")
#debug concat("sphere = ", str(f_sphere(0.3, -0.2, 0.4, 0.25), 0, 10), "\n")
#debug concat("superellipsoid = ", str(f_superellipsoid(0.3, -0.2, 0.4, 0.5, 1.5), 0, 10), "\n")
#debug concat("th = ", str(f_th(0.3, -0.2, -0.4), 0, 10), "\n")
#debug concat("torus = ", str(f_torus(0.9, 0.1, 0.3, 0.8, 0.2), 0, 10), "\n")
#debug concat("torus2 = ", str(f_torus2(0.9, 0.1, 0.3, 1.2, 0.8, 0.2), 0, 10), "\n")
#debug concat("helix1_circle = ", str(f_helix1(0.7, 0.3, -0.4, 2, 5, 0.1, 0.8, 1, 1, 0), 0, 10), "\n")
#debug concat("helix1_square = ", str(f_helix1(-0.5, 1.3, 0.6, 3, 2, 0.15, 0.7, 0.5, 0, 30), 0, 10), "\n")
#debug concat("helix1_rounded = ", str(f_helix1(0.2, -0.8, 0.9, 1, 4, 0.2, 0.9, 2, 0.5, 45), 0, 10), "\n")
#debug concat("helix2_circle = ", str(f_helix2(0.3, 0.5, -0.2, 0, 3, 0.3, 0.4, 0, 1, 0), 0, 10), "\n")
#debug concat("helix2_diamond = ", str(f_helix2(-0.6, 1.1, 0.4, 0, 2, 0.3, 0.5, 0, 2, 0), 0, 10), "\n")
#debug concat("uses_internal = ", str(F_uses_internal(0.2, 0.7, -0.1), 0, 10), "\n")
