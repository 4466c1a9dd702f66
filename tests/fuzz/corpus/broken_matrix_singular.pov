// error: 3:1: transform is singular
// POV-Ray: "Singular matrix"; no inverse takes a ray into the box.
box { -1, 1
  matrix < 1, 0, 0,
           0, 0, 0,
           0, 0, 1,
           0, 0, 0 >
}

