// error: 4:8: a mesh triangle's corner is not finite
// (issue 45) once: one infinite vertex made the whole mesh vanish, exit 0 and no word.
camera { location -5 * z look_at 0 }
mesh { triangle { <0, 0, 0>, <1, 0, 0>, <0, 1e400, 0> } triangle { 0, x, y } }
