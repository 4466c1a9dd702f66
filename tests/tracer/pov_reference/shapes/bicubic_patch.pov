// bicubic_patch against POV-Ray 3.7 (tests/tracer/pov_reference_test.cpp,
// clock 0 and 0.5): a type 0 saddle cut until flat within 0.02 of the
// world, squashed unevenly (POV-Ray measures flatness and normals after
// the transforms), its middle point rising with clock; a type 1 dome
// quarter whose first row is one point (its normal there is POV-Ray's
// fallback <1, 0, 0>), textured through uv_vectors and turning with
// clock; a type 1 patch of two triangles (no steps), its normals blended
// across them.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.3, 0> angle 58 }
light_source { <4, 6, -5> color rgb 1 }
light_source { <-5, 3, -2> color rgb 0.3 }
background { color rgb <0.1, 0.1, 0.3> }
plane { y, -0.6 pigment { checker color rgb 0.9 color rgb 0.5 } }
bicubic_patch { type 0 flatness 0.02 u_steps 4 v_steps 4
  <0, 0, 0>, <1, 1, 0>, <2, -1, 0>, <3, 0, 0>,
  <0, 1, 1>, <1, 0.8 * clock, 1>, <2, 0, 1>, <3, 1, 1>,
  <0, -1, 2>, <1, 0, 2>, <2, 0, 2>, <3, -1, 2>,
  <0, 0, 3>, <1, -1, 3>, <2, 1, 3>, <3, 0, 3>
  pigment { color rgb <1, 0.5, 0.2> } finish { phong 0.6 }
  translate <-1.5, 0, -1.5> scale <0.6, 0.35, 0.5> rotate y * 20 translate <-1.5, 0.3, 0.3>
}
bicubic_patch { type 1 flatness 0.001 u_steps 3 v_steps 3
  uv_vectors <0, 0> <1, 0> <1, 1> <0, 1>
  <0, 1, 0> <0, 1, 0> <0, 1, 0> <0, 1, 0>
  <0.8, 1, 0> <0.8, 1, 0.45> <0.45, 1, 0.8> <0, 1, 0.8>
  <1, 0.5, 0> <1, 0.5, 0.56> <0.56, 0.5, 1> <0, 0.5, 1>
  <1, 0, 0> <1, 0, 0.56> <0.56, 0, 1> <0, 0, 1>
  pigment { uv_mapping checker color rgb <0.2, 0.8, 0.3> color rgb 1 scale 0.25 }
  finish { phong 0.4 }
  scale 1.3 rotate y * (200 + 90 * clock) translate <1.5, -0.6, 0.2>
}
bicubic_patch { type 1 u_steps 0 v_steps 0,
  <-1, 0, 0>, <-0.3, 0.6, 0>, <0.3, 0.6, 0>, <1, 0, 0>,
  <-1, 0.3, 0.5>, <-0.3, 0.9, 0.5>, <0.3, 0.9, 0.5>, <1, 0.3, 0.5>,
  <-1, 0.3, 1>, <-0.3, 0.9, 1>, <0.3, 0.9, 1>, <1, 0.3, 1>,
  <-1, 0, 1.5>, <-0.3, 0.6, 1.5>, <0.3, 0.6, 1.5>, <1, 0, 1.5>
  pigment { color rgb <0.4, 0.6, 1> } finish { phong 0.5 }
  rotate x * -30 translate <0.2, 0.6, 2.2>
}
