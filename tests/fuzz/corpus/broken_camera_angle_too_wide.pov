// error: 2:30: between 0 and 180
camera { location <0, 0, -5> angle 200 }

