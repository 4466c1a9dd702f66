// error: 2:23: an orthographic camera's angle must lie in
camera { orthographic angle 180 location <0, 0, -5> look_at 0 }
