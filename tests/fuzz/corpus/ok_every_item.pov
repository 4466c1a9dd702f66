// Every scene item and modifier of the language, once each.
camera { perspective location <0, 2, -10> direction z right x * 4/3 up y sky y angle 50 look_at 0 }
light_source { <10, 10, -10>, White }
light_source { <-10, 10, -10>, rgb 0.5 shadowless }
light_source { <0, 10, 0>, rgb 1 spotlight point_at 0 radius 10 falloff 20 tightness 5 }
light_source { <0, 10, 0>, rgb 1 area_light x, z, 4, 4 adaptive 1 jitter }
background { color rgb <0.1, 0.1, 0.2> }
global_settings { assumed_gamma 1.0 max_trace_level 7 ambient_light rgb 1 radiosity { count 35 } }
#declare Shiny = finish { ambient 0.1 diffuse 0.7 brilliance 1.5 phong 0.9 phong_size 60 specular 0.2 roughness 0.01 reflection 0.1 }
#declare Chequer = texture { pigment { checker Black, White scale 0.5 } finish { Shiny } }
sphere { <0, 1, 0>, 1 texture { Chequer } }
box { <-1, -1, -1>, <1, 1, 1> translate <3, 1, 0> pigment { Blue } no_shadow }
plane { y, 0 pigment { rgb 0.8 } hollow }
polygon { 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> translate <-3, 0, 0> pigment { Green } }
triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
smooth_triangle { <0, 0, 0>, y, <1, 0, 0>, y, <0, 0, 1>, y }
disc { <0, 0.01, 0>, y, 2, 1 }
cylinder { <0, 0, 0>, <0, 2, 0>, 0.3 open translate -5 * x }
cone { <0, 0, 0>, 1, <0, 2, 0>, 0 translate 5 * x }
torus { 1, 0.2 rotate 90 * x }
prism { linear_sweep linear_spline 0, 1, 4, <0, 0>, <1, 0>, <1, 1>, <0, 0> }
union { sphere { 0, 1 } sphere { x, 1 } light_source { <0, 3, 0>, rgb 0.2 } translate z }
intersection { box { -1, 1 } sphere { 0, 1.3 } interior { ior 1.5 } }
difference { box { -1, 1 } sphere { 0, 1.3 inverse } }
merge { sphere { 0, 1 } sphere { y, 1 } }
#declare T = transform { rotate 30 * y scale 2 translate <1, 2, 3> }
object { sphere { 0, 1 } transform T transform { T inverse } matrix <1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0> }
sphere { 0, 1 material { texture { pigment { rgbt <1, 1, 1, 0.9> } } interior { ior 1.33 } } }
sphere { 0, 1 normal { bumps 0.5 } }   // read and ignored with a warning

