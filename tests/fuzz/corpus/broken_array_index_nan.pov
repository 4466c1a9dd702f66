// error: 4:2: an array index must be a finite number, not
// (issue 17, the reliability cases) once: a NaN index passed the range test and wrote outside the array.
#declare A = array[3];
#declare A[sqrt(-1)] = 1;

