// One of POV-Ray's normal perturbations (N, from 0: --declare N=K, POV-Ray's
// Declare=N=K) on a lit ball and floor, its amount and phase moving with
// clock. tests/tracer/pov_reference_test.cpp compares hexant's stills with
// POV-Ray 3.7's (README.md, "Normals").
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (N) #declare N = 0; #end
camera { location <0, 1.5, -4> look_at <0, 0.4, 0> angle 55 }
light_source { <-3, 5, -4>, rgb 1 }
light_source { <4, 2, -3>, rgb 0.4 shadowless }
#declare Bump = normal {
  #switch (N)
    #case (0) bumps 0.6 scale 0.15 #break
    #case (1) dents 1.5 scale 0.3 #break
    #case (2) ripples 0.6 frequency 4 scale 0.5 #break
    #case (3) waves 0.5 frequency 3 scale 0.5 #break
    #case (4) wrinkles 0.7 scale 0.3 #break
    // (moved off the floor: a surface on a cell boundary flips with rounding)
    #case (5) quilted 0.8 control0 0.5 control1 1 scale 0.25 translate 0.1 * y #break
    #case (6) gradient x 0.6 scale 0.2 triangle_wave #break
    #case (7) marble 0.5 turbulence 0.5 scale 0.3 #break
    #case (8) bozo 0.8 scale 0.2 #break
    #case (9) leopard 0.5 scale 0.05 #break
    #case (10) bumps bump_size 0.4 scale <0.5, 0.1, 0.5> no_bump_scale #break
    #case (11) granite 0.4 scale 2 accuracy 0.01 #break
    #case (12) agate 0.4 warp { turbulence 0.3 } scale 0.5 #break
  #end
  phase 0.5 * clock
  bump_size 0.3 + 0.5 * clock
}
#declare Surface = texture { pigment { rgb <0.9, 0.7, 0.5> } normal { Bump } finish { phong 0.6 } }
plane { y, 0 texture { Surface } }
sphere { <0, 0.7, 0>, 0.7 texture { Surface } }
