// error: 3:3: modifier that belongs in this object
sphere { 0, 1
  location <0, 0, 0>
}

