// A scene with #version 3.6 and no assumed_gamma: POV-Ray 3.7 renders it
// without gamma correction (its legacy rule), so mid-tones come out as
// the colours' own values. Shading, a highlight and a sky gradient moving
// with clock.
#version 3.6;
camera { location <0, 1.5, -4> look_at <0, 0.5, 0> }
light_source { <4, 6, -3>, rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.2, 0.3, 0.5>] [1 rgb <0.7, 0.8, 1>] } } }
plane { y, 0 pigment { checker rgb 0.8, rgb <0.3, 0.2, 0.1> } finish { ambient 0.1 diffuse 0.7 } }
sphere { <0, 1, 0>, 1 translate x * (clock - 0.5)
         pigment { rgb <0.9, 0.4, 0.2> } finish { ambient 0.2 diffuse 0.6 phong 0.8 } }
box { <1.3, 0, -0.5>, <2.1, 0.8, 0.3> pigment { rgb 0.5 } finish { ambient 0.5 diffuse 0 } }
