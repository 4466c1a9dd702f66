// error: 3:34: the camera's type (fisheye) must come first
camera {
  location <0, 0, -5> look_at 0  fisheye
}
