// error: 4:3: the sphere's radius is NaN
// Once an invisible sphere and exit 0.
union {
  sphere { <0, 1, 0>, sqrt(-1) }
  box { -1, 1 }
}

