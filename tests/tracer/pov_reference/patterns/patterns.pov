// One of POV-Ray's patterns (P, from 0: --declare P=N, POV-Ray's
// Declare=P=N) on a wall and a ball lit by ambient light only, so that each
// pixel is the pigment's colour itself; its phase and a turn move with
// clock. tests/tracer/pov_reference_test.cpp compares hexant's stills with
// POV-Ray 3.7's (README.md).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (P) #declare P = 0; #end
camera { location <0, 0, -4> look_at <0, 0, 0> angle 60 }
#declare Map = color_map { [0 rgb <1, 0.2, 0.1>] [0.5 rgb <0.1, 0.9, 0.3>] [1 rgb <0.2, 0.3, 1>] }
#declare Pattern = pigment {
  #switch (P)
    #case (0) agate #break
    #case (1) bozo turbulence 0.3 #break
    #case (2) brick scale 0.1 #break
    #case (3) bumps color_map { Map } #break
    #case (4) checker rgb 1, rgb <0.2, 0.1, 0> scale 0.5 #break
    #case (5) dents color_map { Map } #break
    #case (6) gradient x color_map { Map } frequency 2 #break
    #case (7) granite scale 2 #break
    #case (8) hexagon scale 0.3 #break
    #case (9) leopard scale 0.1 color_map { Map } #break
    #case (10) mandel 50 scale 1.5 translate -0.5 * x #break
    #case (11) marble turbulence 0.8 scale 0.5 #break
    #case (12) onion sine_wave scale 0.5 color_map { Map } #break
    #case (13) quilted control0 0.5 control1 1 scale 0.3 color_map { Map } #break
    #case (14) radial frequency 6 #break
    #case (15) ripples scale 0.5 color_map { Map } #break
    #case (16) spiral1 3 scale 0.5 color_map { Map } #break
    #case (17) spiral2 5 scale 0.5 color_map { Map } #break
    #case (18) spotted scale 0.3 color_map { Map } #break
    #case (19) waves scale 0.5 color_map { Map } #break
    #case (20) wood turbulence 0.1 scale 0.2 #break
    #case (21) wrinkles scale 0.5 color_map { Map } #break
    #case (22) bozo warp { turbulence 0.5 octaves 4 omega 0.6 lambda 2.5 } scale 0.5 scallop_wave color_map { Map } #break
    #case (23) gradient y poly_wave 2 phase 0.3 color_map { [0, 0.5 color rgb 0 color rgb 1] [0.5, 1 color rgb <1, 0, 0> color rgb <0, 0, 1>] } #break
    #case (24) planar scale 2 color_map { Map } #break
    #case (25) spherical scale 2 translate x color_map { Map } #break
    #case (26) cylindrical scale 1.5 color_map { Map } #break
    #case (27) boxed scale 1.5 rotate <20, 30, 0> color_map { Map } #break
  #end
  phase 0.5 * clock
  rotate z * 20 * clock
}
#declare Surface = texture { pigment { Pattern } finish { ambient 1 diffuse 0 } }
plane { z, 1 texture { Surface } }
sphere { <1.1, -0.3, -0.5>, 0.8 texture { Surface } }
