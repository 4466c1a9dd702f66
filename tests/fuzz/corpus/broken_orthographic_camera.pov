// error: 3:3: orthographic cameras are not supported
camera {
  orthographic
  location <0, 0, -5>
}

