// error: 2:29: a fisheye camera's angle takes one value
camera { fisheye location 0 angle 120, 60 }
