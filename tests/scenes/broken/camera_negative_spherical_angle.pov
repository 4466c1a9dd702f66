// error: 2:20: a spherical camera's vertical angle must not be negative
camera { spherical angle 360, -10 }
