// diffuse_back.pov: diffuse's second value (POV-Ray 3.7's DiffuseBack):
// paper screens (polygons: no inside to shadow them) lit from behind show the light through them, diffusely
// and without highlights; a screen without it stays dark on its back, one
// with double_illuminate is lit on both sides as from the front. A light
// moves with clock from behind the screens to in front of them.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5> look_at <0, 1, 0> angle 50 }
light_source { <-3 + 4 * clock, 2.5, 3 - 6 * clock> color rgb 1 }
light_source { <0, 4, -6> color rgb 0.3 }
plane { y, 0 pigment { rgb 0.6 } finish { diffuse 0.8 ambient 0 } }
#declare Paper = pigment { rgb <1, 0.9, 0.7> }
polygon { 5, <-2.4, 0.2>, <-0.9, 0.2>, <-0.9, 2.2>, <-2.4, 2.2>, <-2.4, 0.2> pigment { Paper } finish { ambient 0 diffuse 0.6, 0.4 phong 0.5 } }
polygon { 5, <-0.7, 0.2>, <0.7, 0.2>, <0.7, 2.2>, <-0.7, 2.2>, <-0.7, 0.2> pigment { Paper } finish { ambient 0 diffuse 0.6 phong 0.5 } }
polygon { 5, <0.9, 0.2>, <2.4, 0.2>, <2.4, 2.2>, <0.9, 2.2>, <0.9, 0.2> pigment { Paper } finish { ambient 0 diffuse 0.6 } double_illuminate }
