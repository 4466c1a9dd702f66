// mesh and mesh2 against POV-Ray 3.7 (tests/tracer/pov_reference_test.cpp,
// clock 0 and 0.5): a pyramid as mesh (flat and smooth triangles, a face
// with its own texture, inside_vector) turning with clock; a mesh2 written
// by #for loops (a smooth ball of 8 x 12 quads, normals per vertex, two
// textures from a texture_list) moving with clock; a mesh2 of equal
// normals (flat, as POV-Ray reads it).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.8, -5> look_at <0, 0.5, 0> angle 62 }
light_source { <3, 5, -4> color rgb 1 }
light_source { <-4, 3, -2> color rgb 0.3 }
background { color rgb <0.1, 0.1, 0.3> }
#declare T2 = texture { pigment { color rgb <0.2, 0.9, 0.3> } finish { phong 0.5 } }
mesh {
  triangle { <-1, 0, -1>, <1, 0, -1>, <0, 1.5, 0> }
  triangle { <1, 0, -1>, <1, 0, 1>, <0, 1.5, 0> texture { T2 } }
  smooth_triangle { <1, 0, 1>, <0.7, 0.3, 0.7>, <-1, 0, 1>, <-0.7, 0.3, 0.7>, <0, 1.5, 0>, <0, 1, 0> }
  triangle { <-1, 0, 1>, <-1, 0, -1>, <0, 1.5, 0> }
  inside_vector y
  pigment { color rgb <1, 0.6, 0.2> }
  rotate y * (20 + 90 * clock)
  translate <-1.6, 0, 0.5>
}
#declare Rows = 8;
#declare Cols = 12;
mesh2 {
  vertex_vectors { (Rows + 1) * Cols,
    #for (R, 0, Rows) #for (C, 0, Cols - 1)
      <sin(pi * R / Rows) * cos(2 * pi * C / Cols), -cos(pi * R / Rows), sin(pi * R / Rows) * sin(2 * pi * C / Cols)>,
    #end #end }
  normal_vectors { (Rows + 1) * Cols,
    #for (R, 0, Rows) #for (C, 0, Cols - 1)
      <sin(pi * R / Rows) * cos(2 * pi * C / Cols), -cos(pi * R / Rows), sin(pi * R / Rows) * sin(2 * pi * C / Cols)>,
    #end #end }
  texture_list { 2, texture { pigment { color rgb <0.9, 0.3, 0.3> } finish { phong 0.6 } }
                    texture { pigment { color rgb <0.3, 0.4, 0.95> } finish { phong 0.6 } } }
  face_indices { Rows * Cols * 2,
    #for (R, 0, Rows - 1) #for (C, 0, Cols - 1)
      #declare A = R * Cols + C; #declare B = R * Cols + mod(C + 1, Cols);
      <A, B, A + Cols>, mod(R + C, 2), <B, B + Cols, A + Cols>, mod(R + C, 2),
    #end #end }
  scale 0.7 translate <0.4 + 0.6 * clock, 0.7, 0>
}
mesh2 {
  vertex_vectors { 5, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0>, <0.5, 0.5, -0.5> }
  normal_vectors { 5, <0,0,-1>, <0,0,-1>, <0,0,-1>, <0,0,-1>, <0, 0, -1> }
  face_indices { 4, <0, 1, 4>, <1, 2, 4>, <2, 3, 4>, <3, 0, 4> }
  pigment { color rgb <0.9, 0.8, 0.3> }
  translate <1.6, 0, -0.5>
}
plane { y, 0 pigment { checker color rgb 0.8 color rgb 0.5 } }
