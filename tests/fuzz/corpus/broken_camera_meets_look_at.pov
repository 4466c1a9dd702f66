// error: 5:1: the camera's look_at is its location at clock = 0.5
// flags: --frame-count 3
// The camera travels through the point it looks at, at the middle frame
// (once an error with no place, from the renderer).
camera {
  location <0, 1, -5 + 10 * clock>
  look_at <0, 1, 0>
}

