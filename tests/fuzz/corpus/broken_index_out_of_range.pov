// error: 3:15: out of range
#declare A = array[2] { 1, 2 }
#declare B = A[5];

