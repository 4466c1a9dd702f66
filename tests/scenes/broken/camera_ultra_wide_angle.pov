// error: 3:3: ultra_wide_angle cameras are not supported
camera {
  ultra_wide_angle
  location <0, 0, -5>
}
