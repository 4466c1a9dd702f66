// Noise, vector noise and turbulence at points off the lattice, recorded
// from POV-Ray 3.7 for hexant's tests (runtime/texture/pattern/noise.cpp).
#version 3.7;
#include "functions.inc"
global_settings { assumed_gamma 1 noise_generator NG }
#declare TX = function { pattern { gradient x warp { turbulence <1, 0, 0> octaves 1 } } }
#declare TY = function { pattern { gradient y warp { turbulence <0, 1, 0> octaves 1 } } }
#declare TZ = function { pattern { gradient z warp { turbulence <0, 0, 1> octaves 1 } } }
#declare FX = function { pattern { gradient x warp { turbulence <1, 0, 0> octaves 4 omega 0.6 lambda 2.5 } } }
#declare M = function { pattern { marble turbulence 0.7 octaves 5 } }
#declare R = seed(7);
#fopen Out concat("verify_", str(NG, 0, 0), ".txt") write
#declare I = 0;
#while (I < 200)
  #declare P = (<rand(R), rand(R), rand(R)> - 0.5) * 60;
  #write (Out, vstr(3, P, " ", 0, 17), " ", str(f_noise3d(P.x, P.y, P.z), 0, 20), " ",
          str(TX(P.x, P.y, P.z), 0, 20), " ", str(TY(P.x, P.y, P.z), 0, 20), " ", str(TZ(P.x, P.y, P.z), 0, 20), " ",
          str(FX(P.x, P.y, P.z), 0, 20), " ", str(M(P.x, P.y, P.z), 0, 20), "\n")
  #declare I = I + 1;
#end
#fclose Out
camera { location -z look_at 0 }
