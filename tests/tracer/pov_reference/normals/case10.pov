// Case 10: a perturbed camera: the camera's normal { waves } fades out as
// clock goes 0..1 and its phase moves, so the view wobbles then settles.
#version 3.7;
global_settings { assumed_gamma 1.0 }
// (colors.inc left out: Gray60 is rgb 0.6, Yellow rgb <1, 1, 0>)

camera {
  location <20, 30, -40>
  right x*image_width/image_height
  look_at <0, 10, 0>
  angle 70
  normal { waves 0.25*(1 - clock) frequency 8 phase 3.14*clock }
}
background { color rgb <0.08, 0.36, 0.75> }
light_source { <100, 100, -100> color rgb 0.6 }
light_source { <-100, 100, -100> color rgb 0.6 }

#declare Rod = texture { pigment { color rgb <1, 0.9, 0.7> } finish { phong 0.5 } }
box { <-50, -5, -50>, <50, -4, 50> pigment { color rgb <1, 0.75, 0.33> } }
#for (I, 0, 3)
  union {
    sphere { <10, 0, 10>, 4 pigment { color rgb <(I=0), (I=1), (I>=2)> } }
    sphere { <10, 20, 10>, 4 pigment { color rgb <1, 1, 0> } }
    cylinder { <10, 0, 10>, <10, 20, 10>, 2 texture { Rod } }
    cylinder { <10, 0, 10>, <10, 0, -10>, 2 texture { Rod } }
    cylinder { <10, 20, 10>, <10, 20, -10>, 2 texture { Rod } }
    rotate I*90*y
  }
#end
