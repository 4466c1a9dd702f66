// error: 9:5: the scene's meshes hold more than 2 triangles
// flags: --max-triangles 2
// (issue 45) mesh2's faces count as they are read.
camera { location <0, 0, -5> look_at 0 }
mesh2 {
  vertex_vectors { 4, <0, 0, 0>, <1, 0, 0>, <0, 1, 0>, <1, 1, 0> }
  face_indices { 3,
    <0, 1, 2>, <1, 3, 2>,
    <0, 1, 3>
  }
  pigment { rgb 1 }
}
