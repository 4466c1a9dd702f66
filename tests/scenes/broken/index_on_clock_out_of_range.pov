// error: 6:15: out of range
// flags: --frame-count 10
// An array read at an index on clock gives each piece's element; here the
// index reaches 4 before the animation ends.
#declare A = array[2] { 1, 2 }
#declare B = A[clock * 4];
