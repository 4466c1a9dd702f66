// Records POV-Ray 3.7's DNoise (the turbulence warp's vector noise) at
// lattice points (0, Y, Z): a gradient pattern warped by one octave of
// turbulence along one axis reads back that axis's component, which is an
// entry of the noise table 8 or 16 further on than the scalar noise's.
#version 3.7;
global_settings { assumed_gamma 1 }
#declare DX = function { pattern { gradient x warp { turbulence <1, 0, 0> octaves 1 } } }
#declare DY = function { pattern { gradient y warp { turbulence <0, 1, 0> octaves 1 } } }
#declare DZ = function { pattern { gradient z warp { turbulence <0, 0, 1> octaves 1 } } }
#fopen Out "lattice_dnoise.txt" write
#declare I = 0;
#while (I < 3000)
  #declare X = 0;
  #declare Y = mod(I * 13, 53) + int(I / 53) * 0;
  #declare Z = mod(I * 29, 47) + int(I / 47);
  #write (Out, str(X,0,0), " ", str(Y,0,0), " ", str(Z,0,0), " ",
          str(DX(X, Y, Z), 0, 20), " ", str(DY(X, Y, Z), 0, 20), " ", str(DZ(X, Y, Z), 0, 20), "\n")
  #declare I = I + 1;
#end
#fclose Out
camera { location -z look_at 0 }
