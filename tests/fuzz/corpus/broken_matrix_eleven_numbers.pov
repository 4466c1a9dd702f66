// error: 2:15: matrix needs 12 numbers, not 11
sphere { 0, 1 matrix <1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0> }

