// quadric, cubic, quartic, poly and polynomial against POV-Ray 3.7
// (tests/tracer/pov_reference_test.cpp).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.2, 0> angle 42 }
light_source { <-6, 12, -9>, rgb 1 }
light_source { <6, 5, -6>, rgb 0.4 }
background { rgb <0.2, 0.25, 0.3> }
plane { y, -1.2 pigment { checker rgb 0.8, rgb 0.45 } }
// A hyperboloid of one sheet (quadric), clipped to a slab, its waist
// narrowing with clock.
quadric { <1, -1, 1>, <0, 0, 0>, <0, 0, 0>, -0.2 + 0.15 * clock
    clipped_by { box { <-2, -1, -2>, <2, 1, 2> } }
    pigment { rgb <0.9, 0.4, 0.2> }
    translate <-3, 0, 1>
}
// An ellipsoid written as a quadric, in a bounded_by box (POV-Ray drops
// it: "Unnecessary bounding object removed").
quadric { <1, 4, 1>, <0, 0, 0>, <0, 0, 0>, -1
    bounded_by { box { <-1.5, -1, -1.5>, <1.5, 1, 1.5> } }
    pigment { rgb <0.3, 0.8, 0.4> }
    translate <0, -0.6, 2.5>
}
// The piriform (POV-Ray's quartic sample), turning with clock.
quartic {
   < 4.0,  0.0,  0.0,  -4.0, 0.0,  0.0,  0.0,  0.0,  0.0, 0.0,
     0.0,  0.0,  0.0,   0.0, 0.0,  0.0,  0.0,  0.0,  0.0, 0.0,
     0.0,  0.0,  0.0,   0.0, 0.0,  1.0,  0.0,  0.0,  0.0, 0.0,
     0.0,  0.0,  1.0,   0.0, 0.0 >
   sturm
   bounded_by { sphere { <0, 0, 0>, 2 } }
   pigment { rgb <0.5, 0.1, 0.15> }
   finish { phong 1 phong_size 50 }
   scale 1.25
   rotate <0, -30 + 40 * clock, 0>
   translate <0.5, 0.2, -0.5>
}
// A torus as a quartic in POV-Ray's poly syntax (R = 1, r = 0.35),
// bounded by its own box.
#declare R2 = 1;
#declare r2 = 0.35 * 0.35;
poly { 4,
   < 1, 0, 0, 0, 2, 0, 0, 2, 0, -2 * (R2 + r2),
     0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     1, 0, 0, 2, 0, 2 * (R2 - r2), 0, 0, 0, 0,
     1, 0, -2 * (R2 + r2), 0, (R2 - r2) * (R2 - r2) >
   bounded_by { box { <-1.4, -0.4, -1.4>, <1.4, 0.4, 1.4> } }
   pigment { rgb <0.3, 0.5, 1> }
   rotate x * (60 + 30 * clock)
   translate <3, 0.3, 1>
}
// A cubic saddle, x^3 - 3 x y^2 - z = 0 (the monkey saddle), clipped by a sphere.
cubic { < 1, 0, 0, 0, -3, 0, 0, 0, 0, 0,
          0, 0, 0, 0, 0, 0, 0, 0, -1, 0 >
    clipped_by { sphere { 0, 0.9 } }
    pigment { rgb <1, 0.85, 0.3> }
    scale 0.9
    rotate x * -90
    translate <-1.5, 1.6, 2>
}
// A rounded cube of order 6 in polynomial's syntax, x^6 + y^6 + z^6 +
// 4 x^2 y^2 z^2 = r^6, its size growing with clock.
polynomial { 6,
   xyz(6, 0, 0): 1, xyz(0, 6, 0): 1, xyz(0, 0, 6): 1, xyz(2, 2, 2): 4,
   xyz(0, 0, 0): -pow(0.4 + 0.1 * clock, 6)
   bounded_by { sphere { 0, 0.7 } }
   pigment { rgb <0.8, 0.5, 0.9> }
   rotate <20, 30, 0>
   translate <1.7, 1.5, 2.5>
}
