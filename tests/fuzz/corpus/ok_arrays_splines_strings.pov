// Arrays (one to three dimensions, filled later, dimension_size, arrays of
// vectors and objects), splines of every kind called as S(t), seed/rand
// streams, and strings (str, concat, chr, vstr, #debug).
#version 3.7;
global_settings { assumed_gamma 1.0 }

#declare Line = array[4] { 1, 2, 3, 4 }
#declare Grid = array[2][3] { { 1, 2, 3 }, { 4, 5, 6 } }
#declare Cube = array[2][2][2];
#for (I, 0, 1) #for (J, 0, 1) #for (K, 0, 1)
  #declare Cube[I][J][K] = 4 * I + 2 * J + K;
#end #end #end
#if (dimension_size(Line, 1) != 4 | dimension_size(Grid, 2) != 3) #error "dimension_size" #end
#if (Grid[1][2] != 6 | Cube[1][1][0] != 6) #error "indexing" #end
#declare Total = 0;
#for (I, 0, dimension_size(Line, 1) - 1)
  #declare Total = Total + Line[I];
#end
#if (Total != 10) #error "sum" #end
#if (Line[1.7] != 2) #error "an index is truncated" #end
#declare Points = array[3] { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
#if (Points[2].y != 1) #error "array of vectors" #end
#declare Balls = array[2] { sphere { 0, 1 }, sphere { x, 0.5 } }
object { Balls[1] }
union { #for (I, 0, 2) sphere { Points[I], 0.2 } #end }

#declare L = spline { linear_spline 0, <0, 0, 0> 1, <2, 4, 6> 2, <2, 4, 0> }
#declare P = L(0.5);
#if (P.x != 1 | P.y != 2 | P.z != 3) #error "linear_spline" #end
#declare P = L(1.5);
#if (P.z != 3) #error "linear_spline, second piece" #end
#declare Q = spline { quadratic_spline 0, <0, 0> 1, <1, 1> 2, <2, 0> 3, <3, 1> }
#declare C = spline { cubic_spline -1, <0, 0> 0, <0, 0> 1, <1, 1> 2, <2, 0> 3, <3, 3> }
#declare N = spline { natural_spline 0, <0, 0> 1, <1, 1> 2, <2, 0> }
#declare Qv = Q(1.5);
#declare Cv = C(0.5);
#declare Nv = N(1);
#if (Nv.x != 1 | Nv.y != 1) #error "natural_spline passes its keys" #end
// Values POV-Ray 3.7 printed for these two (vstr(2, V, ",", 0, 4)):
// quadratic 1.5000,0.7500 and cubic 0.4375,0.5625.
#if (abs(Qv.u - 1.5) > 1e-6 | abs(Qv.v - 0.75) > 1e-6) #error "quadratic_spline" #end
#if (abs(Cv.u - 0.4375) > 1e-6 | abs(Cv.v - 0.5625) > 1e-6) #error "cubic_spline" #end

#declare S1 = seed(7);
#declare S2 = seed(7);
#declare R1 = rand(S1);
#declare R2 = rand(S2);
#if (R1 != R2) #error "same seed, same stream" #end
#declare R3 = rand(S1);
#if (R3 = R1 | R3 < 0 | R3 > 1) #error "a stream moves on" #end

#declare Name = concat("ball", str(3, 0, 0), chr(95), str(2.5, 5, 2));
#debug concat(Name, "\n")
#declare Padded = str(7, -3, 0);             // zero-padded to width 3
#debug concat("[", Padded, "] [", vstr(3, <1, 2, 3>, ", ", 0, 1), "]\n")
#declare Empty = "";
#declare Joined = concat(Empty, "a", "b");
#debug concat(Joined, "\n")

