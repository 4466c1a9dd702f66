// A static scene for comparing hexant with POV-Ray 3.7 pixel by pixel (see
// README.md here): every shape kind hexant renders, a checker, phong and
// specular highlights, a shadow, an ambient_light and a shadowless light.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb <1, 0.95, 0.9> }

camera {
    location <0.3, 3.2, -7>
    look_at <0, 0.8, 0>
    angle 48
}

light_source { <-5, 9, -6>, rgb 1 }
light_source { <6, 3, -4>, rgb <0.2, 0.2, 0.3> shadowless }
background { rgb <0.1, 0.12, 0.2> }

plane {
    y, 0
    pigment { checker rgb <0.8, 0.8, 0.75>, rgb <0.35, 0.35, 0.4> }
    finish { ambient 0.1 diffuse 0.7 }
}
sphere {
    <-1.3, 1, 0.5>, 1
    pigment { rgb <0.85, 0.3, 0.2> }
    finish { phong 0.7 phong_size 60 }
}
box {
    <-0.5, 0, -0.5>, <0.5, 1.2, 0.5>
    rotate y * 30 translate <1.4, 0, 0.3>
    pigment { rgb <0.3, 0.6, 0.9> }
    finish { specular 0.5 roughness 0.02 diffuse 0.8 }
}
cylinder { <-2.8, 0, 2>, <-2.8, 2.2, 2>, 0.35 pigment { rgb <0.9, 0.8, 0.2> } }
cone { <2.6, 0, 2.2>, 0.6, <2.6, 1.6, 2.2>, 0.1 pigment { rgb <0.4, 0.85, 0.4> } }
torus { 0.6, 0.18 rotate x * 60 translate <0.2, 0.75, -1.6> pigment { rgb <0.8, 0.4, 0.9> } }
disc { <0.4, 0.01, 1.6>, y, 0.7, 0.3 pigment { rgb <1, 1, 1> } }
triangle { <-0.6, 2.2, 1.5>, <0.6, 2.2, 1.5>, <0, 3.1, 1.8> pigment { rgb <0.9, 0.5, 0.1> } }
polygon {
    5, <1.5, 1.8, 2.5>, <2.5, 1.8, 2.5>, <2.5, 2.8, 2.5>, <1.5, 2.8, 2.5>, <1.5, 1.8, 2.5>
    pigment { rgb <0.2, 0.8, 0.8> }
}
prism {
    linear_sweep linear_spline 0, 0.5, 4, <-0.4, -0.3>, <0.4, -0.3>, <0, 0.4>, <-0.4, -0.3>
    translate <-0.2, 0, -2.6>
    pigment { rgb <0.95, 0.95, 0.5> }
}
