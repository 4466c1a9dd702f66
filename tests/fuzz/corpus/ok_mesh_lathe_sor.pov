mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> } smooth_triangle { <1,0,0>, <0,0,1>, <1,1,0>, <0,0,1>, <0,1,0>, <0,0,1> texture { pigment { rgb x } } } inside_vector z rotate y * clock * 90 }
mesh2 { vertex_vectors { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> } uv_vectors { 4, <0,0>, <1,0>, <1,1>, <0,1> }
  texture_list { 2, texture { pigment { rgb 1 } } texture { pigment { rgb y } } }
  face_indices { 2, <0,1,2>, 0, <0,2,3>, 1 } translate x }
lathe { cubic_spline 6, <0,-1>, <0.5,-0.5>, <0.7,0>, <0.4 + 0.2 * clock, 0.4>, <0.5,0.7>, <0,0.9> translate -x }
sor { 6, <0.3,-0.7>, <0.4,-0.5>, <0.6,-0.1>, <0.3,0.3>, <0.5,0.6>, <0.6,0.8> open translate 2 * x }
camera { location <0.5, 0.5, -4> look_at 0 }
light_source { <2, 3, -4> rgb 1 }
