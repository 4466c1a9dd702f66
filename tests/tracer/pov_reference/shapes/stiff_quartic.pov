// Two stiff quartics from POV-Ray's distribution (objects/quartic/quarcyl
// and steiner, shapesq.inc's Steiner_Surface), turning with clock. Their
// ray polynomials are ill-conditioned where they flatten, so a hit point
// lies far from the surface by more than its coordinates' rounding; a
// shadow ray leaving from too near finds the surface it left (speckles).
#version 3.7;
global_settings { assumed_gamma 1.0 }
quartic {
   < 0.0,  0.0,  0.0,  0.0,  1.0,  0.0,  0.0,  0.0,  0.0,  0.01,
     0.0,  0.0,  0.0,  0.0,  0.0,  0.0,  0.0,  0.0,  0.0,  0.0,
     0.0,  0.0,  0.0,  1.0,  0.0,  0.0,  0.0,  0.0,  0.0,  0.0,
     0.0,  0.0,  0.01, 0.0, -0.01 >
   bounded_by { sphere { <0, 0, 0>, 2 } }
   pigment { rgb 0.4 }
   finish { phong 1.0 phong_size 50 ambient 0.2 diffuse 0.8 }
   scale 1.5
   rotate <-30, 20 + 40 * clock, 50>
   translate <-1.6, 0, 3>
}
quartic {  // shapesq.inc's Steiner_Surface
   < 0,   0,   0,  0,  1,   0,   0,   1,   0,   0,
     0,   0,   0,  0,  1,   0,   0,   0,   0,   0,
     0,   0,   0,  1,  0,   0,   0,   0,   0,   0,
     0,   0,   0,  0,  0>
   pigment { rgb <0.9, 0.1, 0.2> }
   finish { phong 1 phong_size 10 }
   bounded_by { sphere { <0, 0, 0>, 1 } }
   scale 2.2
   rotate <50, -25 + 60 * clock, 0>
   translate <1.6, 0, 3>
}
camera { location <0, 0, -3> angle 75 up y right x * image_width / image_height }
light_source { <200, 30, -300> rgb 1 }
light_source { <-200, 100, -300> rgb 0.6 }
background { rgb 0.03 }
