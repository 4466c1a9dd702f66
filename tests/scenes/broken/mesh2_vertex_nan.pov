// error: 3:26: entry 1 of vertex_vectors is not finite
// (issue 45) once: NaN vertices in mesh2 were accepted where a plain triangle's NaN corner is an error.
mesh2 { vertex_vectors { 3, <0, 0, 0>, <sqrt(-1), 0, 0>, <0, 1, 0> } face_indices { 1, <0, 1, 2> } }
