// algebra.pov: algebraic surfaces in motion. A torus written as a quartic
// stands on edge and turns about the vertical, its tube thickening with
// clock (its coefficients are functions of clock); POV-Ray's piriform
// quartic spins tilted on its tip, precessing and blurring like a top; a hyperboloid quadric is cut by a plane that sweeps
// down through it with clock (clipped_by), showing its open waist; and a
// sextic rounded cube, written term by term in polynomial { }, tumbles. All
// are unbounded surfaces given a place by their bounded_by and clipped_by,
// as in POV-Ray. A cyclic 16-frame animation (algebra.ini).
//
// Render with hexant:   build/hexant render examples/algebra.pov examples/algebra.ini --spp 8
// Render with POV-Ray:  povray examples/algebra.ini examples/algebra.pov
#version 3.7;

global_settings { assumed_gamma 1.0 }

camera {
    location <0, 3.2, -7.5>
    look_at <0, 0.6, 0>
    angle 44
    right x * image_width / image_height
}
light_source { <-5, 9, -7>, rgb 1 }
light_source { <6, 4, -4>, rgb 0.35 }
background { rgb <0.1, 0.1, 0.14> }
plane { y, 0 pigment { checker rgb <0.75, 0.72, 0.66>, rgb <0.35, 0.38, 0.45> } }

#declare Tau = 2 * pi;

// The torus (R = 1, r from 0.25 to 0.4 and back) as a quartic in poly's
// order, standing on edge, a half turn about the vertical in the cycle.
#declare r2 = pow(0.25 + 0.15 * (0.5 - 0.5 * cos(Tau * clock)), 2);
#declare a = 1 - r2;
poly { 4,
    < 1, 0, 0, 0, 2, 0, 0, 2, 0, 2 * a - 4,
      0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
      1, 0, 0, 2, 0, 2 * a, 0, 0, 0, 0,
      1, 0, 2 * a - 4, 0, a * a >
    bounded_by { box { <-1.5, -0.45, -1.5>, <1.5, 0.45, 1.5> } }
    pigment { rgb <0.25, 0.45, 0.95> }
    finish { phong 0.7 phong_size 40 }
    rotate x * 90
    rotate y * 180 * clock
    translate <-1.9, 1.45, 1.2>
}

// The piriform, 4 x^4 - 4 x^3 + y^2 + z^2 = 0, tilted on its tip,
// turning 60 degrees a frame about the vertical.
quartic {
    < 4, 0, 0, -4, 0, 0, 0, 0, 0, 0,
      0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
      0, 0, 0, 0, 0, 1, 0, 0, 0, 0,
      0, 0, 1, 0, 0 >
    bounded_by { sphere { <0.5, 0, 0>, 0.8 } }
    pigment { rgb <0.7, 0.1, 0.15> }
    finish { phong 1 phong_size 60 }
    scale 1.3
    rotate z * 65
    rotate y * 960 * clock
    translate <0.3, 0, -0.6>
}

// A hyperboloid of one sheet, x^2 - y^2 + z^2 = 0.15, cut by a plane
// that sinks through it and rises again.
quadric { <1, -1, 1>, <0, 0, 0>, <0, 0, 0>, -0.15
    clipped_by { box { <-2, -0.9, -2>, <2, 0.9, 2> } }
    clipped_by { plane { y, 0.9 - 1.4 * (0.5 - 0.5 * cos(Tau * clock)) } }
    pigment { rgb <1, 0.6, 0.2> }
    finish { phong 0.5 }
    translate <2.4, 0.95, 1.4>
}

// A rounded cube of order 6, x^6 + y^6 + z^6 + 4 x^2 y^2 z^2 = 0.4^6,
// tumbling.
polynomial { 6,
    xyz(6, 0, 0): 1, xyz(0, 6, 0): 1, xyz(0, 0, 6): 1, xyz(2, 2, 2): 4,
    xyz(0, 0, 0): -pow(0.4, 6)
    bounded_by { sphere { 0, 0.7 } }
    pigment { rgb <0.5, 0.85, 0.45> }
    finish { phong 0.6 }
    rotate <360 * clock, 180 * clock, 0>
    translate <1.8, 0.6, -1.2>
}
