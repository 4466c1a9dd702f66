// error: 4:15: used before it is set
#declare A = array[3];
#declare A[0] = 1;
#declare B = A[2];

