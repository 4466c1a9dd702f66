// uv_mapping against POV-Ray 3.7 (tests/tracer/pov_reference_test.cpp,
// clock 0 and 0.5): each kind POV-Ray 3.7 maps (sphere, box, torus,
// lathe, sor, mesh2's uv_vectors) and one it does not (a cylinder: the
// world x and y of the hit), at pigment, normal and texture level; the
// transforms written after uv_mapping act in uv space, the object's own
// (turning with clock) carry the mapping with it, and a declared
// uv-mapped pigment ignores a scale written outside it, as in POV-Ray.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.2, -7> look_at <0, 0.6, 0> angle 55 }
light_source { <-5, 8, -6> color rgb 1 }
light_source { <4, 3, -5> color rgb 0.3 }
background { rgb <0.1, 0.1, 0.2> }
plane { y, -1 pigment { color rgb 0.5 } }
#declare Checks = pigment { uv_mapping checker rgb <1, 0.3, 0.2>, rgb 0.9 scale 0.125 }
sphere { 0, 0.9
  pigment { uv_mapping image_map { png "tiles.png" interpolate 2 } }
  rotate y * 90 * clock translate <-2.4, 0.2, 0>
  no_shadow  // (tiles.png is partly clear: POV-Ray filters shadows, hexant not yet)
}
box { -0.7, 0.7
  texture { uv_mapping pigment { checker rgb <0.2, 0.5, 1>, rgb 0.95 scale 0.0625 }
            normal { bumps 0.6 scale 0.02 } finish { phong 0.4 } }
  rotate <30, 40 + 60 * clock, 0> translate <0, 0.1, 0>
}
torus { 0.7, 0.3
  pigment { Checks scale 4 }
  normal { uv_mapping gradient x 0.5 scale 0.1 }
  rotate x * (-50 + 20 * clock) translate <2.4, 0.3, 0>
}
lathe { linear_spline 4, <0.2, 0>, <0.7, 0.3>, <0.5, 1>, <0.2, 1.3>
  pigment { uv_mapping gradient x color_map { [0 rgb <1, 0.8, 0.2>] [0.5 rgb <0.2, 0.8, 0.4>] [1 rgb <1, 0.8, 0.2>] } scale <0.25, 1, 1> }
  rotate y * 45 * clock translate <-1.3, -1, -2>
}
sor { 4, <0, 0>, <0.5, 0.1>, <0.3, 0.9>, <0.5, 1.1>
  pigment { uv_mapping checker rgb <0.9, 0.2, 0.8>, rgb 0.2 scale <0.125, 0.25, 1> }
  translate <1.3, -1, -2>
}
mesh2 {
  vertex_vectors { 4, <-0.8, 0, 0>, <0.8, 0, 0>, <0.8, 1.2, 0>, <-0.8, 1.2, 0> }
  uv_vectors { 4, <0, 0>, <1.5, 0>, <1.5, 1>, <0, 1> }
  face_indices { 2, <0, 1, 2>, <0, 2, 3> }
  pigment { uv_mapping image_map { png "tiles.png" } }
  translate <-0.2, 1.1, 2.5>
  no_shadow
}
cylinder { <-0.3, -1, 1.2>, <-0.3, 0.6, 1.2>, 0.35
  pigment { uv_mapping checker rgb 1, rgb <0.2, 0.3, 0.1> scale 0.2 }
  translate <-3.3 + clock, 0, -2.6>
}
