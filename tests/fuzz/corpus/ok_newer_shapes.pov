// Fuzz seed: the shapes added after the first ones, each moving with
// clock somewhere: isosurface, sphere_sweep, blob, lathe, sor, prism,
// superellipsoid, julia_fractal, bicubic_patch, poly, ovus.
camera { location <0, 2, -8> look_at 0 }
light_source { <-3, 5, -4> rgb 1 }
#declare F = function(x, y, z, r) { x * x + y * y + z * z - r * r }
isosurface { function { F(x, y, z, 0.5 + clock) } contained_by { box { -2, 2 } } accuracy 0.01 translate <-3, 2, 0> pigment { rgb 1 } }
sphere_sweep { b_spline 4, <-1, 0, 0>, 0.2, <0, 1, 0>, 0.3, <1, 0, 0>, 0.2, <2, 1, 0>, 0.1 translate <-1, 2, 0> pigment { rgb x } }
blob { threshold 0.6 sphere { 0, 1, 1 } sphere { x * clock, 1, 1 } cylinder { 0, y, 0.5, -2 } translate <1.5, 2, 0> pigment { rgb y } }
lathe { bezier_spline 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> translate <-3, 0, 0> pigment { rgb z } }
sor { 4, <0, 0>, <0.5, 0>, <0.3, 1>, <0, 1.2> open translate <-1.5, 0, 0> pigment { rgb 1 } }
prism { linear_sweep linear_spline 0, 1, 4, <0, 0>, <1, 0>, <0, 1>, <0, 0> translate <0, 0, 0> pigment { rgb x } }
superellipsoid { <0.1 + clock, 3> translate <1.5, 0, 0> pigment { rgb y } }
julia_fractal { <-0.1, 0.6, 0, 0> quaternion sqr max_iteration 8 precision 10 translate <3, 0, 0> pigment { rgb z } }
bicubic_patch { type 1 u_steps 3 v_steps 3
  <0, 0, 0>, <1, 0, 0>, <2, 0, 0>, <3, 0, 0>, <0, 1, 0>, <1, 1, 1>, <2, 1, 1>, <3, 1, 0>,
  <0, 2, 0>, <1, 2, 1>, <2, 2, 1>, <3, 2, 0>, <0, 3, 0>, <1, 3, 0>, <2, 3, 0>, <3, 3, 0>
  scale 0.5 translate <-3, -2, 0> pigment { rgb 1 } }
poly { 4, <1, 0, 0, 0, 1, 0, 0, 0, 0, -0.5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1> translate <0, -2, 0> pigment { rgb x } }
