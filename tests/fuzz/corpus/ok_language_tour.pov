// Directives and expressions across the language: every one of them must run.
#version 3.7; global_settings { assumed_gamma 1.0 }

#declare Count = 0;
#while (Count < 4)
  #declare Count = Count + 1;
#end
#for (I, 1, 9, 2)
  #local Odd = I;
#end
#if (Count = 4 & Odd = 9 | false)
  #declare Path = "while and for";
#elseif (Count > 4)
  #error "unreachable"
#else
  #error "the loops went wrong"
#end
#ifdef (Path) #declare Seen = yes; #end
#ifndef (Nothing) #declare Seen2 = on; #end
#undef Seen2
#switch (Count)
  #case (1) #error "not 1"
  #range (2, 5) #declare Ranged = 1; #break
  #else #error "not else"
#end
// POV-Ray's precedence: unary minus, *, +, comparisons, & and | left to right, ?:
#declare E = (-2 * 3 + 4 < 0 & 1 | 0 ? 10 : 20);   // POV-Ray reads ?: only inside ( )
#if (E != 10) #error "precedence" #end
#declare V = <1, 2, 3> * 2 + 1;            // float promotion
#declare W = <1, 2> + <1, 2, 3, 4, 5>;      // sizes pad with zeros
#declare C = color red 1 green .5 filter .25;
#declare D0 = srgb <.5, .5, .5>; #declare D = rgbft <.1, .2, .3, .4, .5> + D0;
#if (V.y != 5 | W.t != 4 | C.filter != .25 | C.blue != 0) #error "components" #end
#declare F = abs(-1) + sin(pi/2) + cos(0) + tan(0) + asin(1) + acos(1) + atan(0) + atan2(1, 1)
           + sqrt(4) + pow(2, 3) + exp(0) + log(100) + ln(1) + min(1, 2, 3) + max(1, 2) + mod(7, 3)
           + div(7, 2) + int(-1.5) + floor(1.5) + ceil(1.5) + radians(180) + degrees(pi)
           + select(-1, 1, 2) + select(0, 1, 2, 3) + vlength(<3, 4, 0>) + vdot(x, y);
#declare N = vnormalize(<0, 3, 4>) + vcross(x, y) + vrotate(x, <0, 0, 90>) + vaxis_rotate(x, z, 90);
#declare S = concat(str(F, 0, 3), " ", chr(65), " ", vstr(3, N, ",", 0, 2));
#debug concat(S, "\n")
#declare A = array[2][3] { {1, 2, 3}, {4, 5, 6} };
#declare A[1][2] = 60;
#if (dimension_size(A, 2) != 3 | A[1][2] != 60) #error "arrays" #end
#declare Path3 = spline { cubic_spline -1, <0, 0, 0> 0, <1, 0, 0> 1, <1, 1, 0> 2, <0, 1, 0> }
#declare P = Path3(0.5);
#declare R = seed(42);
#declare Random = rand(R);
#if (Random < 0 | Random > 1) #error "rand" #end
Part_Ball(<0, 1, 0>, Red)
object { Part_Ring translate x * Count }

