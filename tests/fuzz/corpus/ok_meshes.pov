// Fuzz seed: mesh and mesh2 with every list (normals, uv, textures and
// their indices, inside_vector), moving with clock.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -4> look_at 0 }
light_source { <-3, 5, -4> rgb 1 }
mesh {
  triangle { <-1, 0, 0>, <0, 1, 0>, <1, 0, 0> }
  smooth_triangle { <-1, 0, 0>, <0, 0, -1>, <0, -1, 0>, <0, 0, -1>, <1, 0, 0>, <0, 0, -1> texture { pigment { rgb x } } }
  triangle { 0, 0, x }
  inside_vector y
  pigment { rgb 1 } rotate y * 90 * clock
}
mesh2 {
  vertex_vectors { 4, <0, 0, 0>, <1, 0, 0>, <0, 1, 0>, <0, 0, 1> }
  normal_vectors { 2, <0, 0, -1>, <1, 1, 1> }
  uv_vectors { 3, <0, 0>, <1, 0>, <0, 1> }
  texture_list { 2, texture { pigment { rgb y } }, texture { pigment { image_map { png "plasma2.png" } } } }
  face_indices { 3, <0, 1, 2>, 0, <1, 2, 3>, 1, <0, 2, 3>, 0, 1, 0 }
  normal_indices { 3, <0, 0, 0>, <1, 1, 1>, <0, 1, 0> }
  uv_indices { 3, <0, 1, 2>, <0, 1, 2>, <2, 1, 0> }
  inside_vector z
  translate <-1, 0, 0> scale 1 + clock
}
