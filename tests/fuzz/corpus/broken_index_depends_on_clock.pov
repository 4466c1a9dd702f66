// error: 4:15: depends on clock
// flags: --frame-count 10
#declare A = array[2] { 1, 2 }
#declare B = A[clock];

