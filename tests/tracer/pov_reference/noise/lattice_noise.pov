// Records POV-Ray 3.7's Noise (generator 2, the default) at lattice
// points: each gives one entry of its table (runtime/texture/pattern/noise_table.cpp).
#version 3.7;
#include "functions.inc"
global_settings { assumed_gamma 1 }
#fopen Out "lattice_noise.txt" write
#declare I = 0;
#while (I < 3000)
  #declare X = mod(I * 7, 61) + 1;
  #declare Y = mod(I * 13, 53) + 1;
  #declare Z = mod(I * 29, 47) + 1 + int(I / 2000) * 50;
  #write (Out, str(X,0,0), " ", str(Y,0,0), " ", str(Z,0,0), " ",
          str(f_noise3d(X, Y, Z), 0, 20), "\n")
  #declare I = I + 1;
#end
#fclose Out
camera { location -z look_at 0 }
