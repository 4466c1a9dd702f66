// error: 3:3: mesh_camera cameras are not supported
camera {
  mesh_camera { 1 0 mesh { triangle { 0, x, y } } }
  location <0, 0, -5>
}
