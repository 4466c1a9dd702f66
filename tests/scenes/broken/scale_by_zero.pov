// error: 2:15: scale by zero
sphere { 0, 1 scale 0 }
