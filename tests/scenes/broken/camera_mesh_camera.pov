// error: 3:3: mesh_camera: rays per pixel may not be 0
camera {
  mesh_camera { 0 0 mesh { triangle { 0, x, y } } }
  location <0, 0, -5>
}
