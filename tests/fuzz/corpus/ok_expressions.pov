// Expressions: POV-Ray's precedence (unary, * /, + -, comparisons, &, |,
// ? :), vectors of 2 to 5 components with float promotion, component access,
// the built-in constants and functions. Every result is checked with #error,
// so POV-Ray and hexant must agree on all of it.
#version 3.7;
global_settings { assumed_gamma 1.0 }

#macro Near(A, B) (abs((A) - (B)) < 1e-6) #end

#if (1 + 2 * 3 != 7)             #error "* before +" #end
#if (-2 * -3 != 6)               #error "unary minus" #end
#if (10 - 4 - 3 != 3)            #error "- is left-associative" #end
#if (8 / 4 / 2 != 1)             #error "/ is left-associative" #end
#if (!(1 < 2) != 0)              #error "!" #end
#if ((1 < 2) + (2 <= 2) + (3 > 2) + (2 >= 3) + (1 = 1) + (1 != 1) != 4) #error "comparisons" #end
#if ((1 | 0 & 0) != 0)           #error "& and | share a level, left to right" #end
#if ((0 ? 1 : 2) != 2)           #error "?:" #end
#if ((1 ? 0 ? 5 : 6 : 7) != 6)   #error "nested ?:" #end
#if (1 + 1 = 2 ? 0 : 1)          #error "?: binds loosest" #end
#if (true + yes + on != 3 | false + no + off != 0) #error "booleans" #end

#declare V2 = <1, 2>;
#declare V3 = <1, 2, 3>;
#declare V4 = <1, 2, 3, 4>;
#declare V5 = <1, 2, 3, 4, 5>;
#if (V2.u != 1 | V2.v != 2)      #error ".u .v" #end
#if (V4.t != 4)                  #error ".t" #end
#declare P = V3 * 2 + 1;         // float promotion
#if (P.x != 3 | P.y != 5 | P.z != 7) #error "promotion" #end
#declare Q = V3 * <2, 3, 4>;     // component-wise
#if (Q.z != 12)                  #error "component-wise *" #end
#declare R = -V3;
#if (R.y != -2)                  #error "unary minus of a vector" #end
#declare W = x + 2 * y + 3 * z;
#if (W.x != 1 | W.y != 2 | W.z != 3) #error "x y z" #end
#if (vlength(V3 - V3) != 0)      #error "vlength" #end
#if (!Near(vdot(V3, V3), 14))    #error "vdot" #end
#declare C = vcross(x, y);
#if (C.z != 1)                   #error "vcross" #end
#declare Rot = vrotate(x, 90 * z);
#if (!Near(Rot.y, 1))            #error "vrotate" #end
#declare Ax = vaxis_rotate(x, y, 90);
#if (!Near(Ax.z, -1))            #error "vaxis_rotate" #end
#declare Nn = vnormalize(<0, 0, 5>);
#if (Nn.z != 1)                  #error "vnormalize" #end

#if (!Near(pi, 3.14159265358979)) #error "pi" #end
#if (!Near(sin(pi / 6), 0.5) | !Near(cos(0), 1) | !Near(tan(pi / 4), 1)) #error "trig" #end
#if (!Near(atan2(1, 1), pi / 4) | !Near(asin(1), pi / 2) | !Near(acos(1), 0)) #error "inverse trig" #end
#if (!Near(degrees(pi), 180) | !Near(radians(90), pi / 2)) #error "angles" #end
#if (sqrt(16) != 4 | pow(2, 10) != 1024 | !Near(exp(1), 2.718281828459) | !Near(ln(exp(2)), 2)) #error "powers" #end
#if (!Near(log(1000), 3))        #error "log is base 10" #end
#if (int(-2.7) != -2 | floor(-2.7) != -3 | ceil(-2.2) != -2) #error "rounding" #end
#if (mod(-7, 3) != -1 | div(-7, 2) != -3) #error "mod and div truncate" #end
#if (min(4, 2, 8) != 2 | max(4, 2, 8) != 8 | abs(-3) != 3) #error "min max abs" #end
#if (select(-1, 10, 20) != 10 | select(1, 10, 20) != 20 | select(0, 1, 2, 3) != 2) #error "select" #end
#declare Tiny = 1.5e-3 + 2E2 + .5;
#if (!Near(Tiny, 200.5015))      #error "number forms" #end
#debug concat("expressions: ", vstr(5, V5, ",", 0, 0), "\n")
sphere { V3, 0.5 }

