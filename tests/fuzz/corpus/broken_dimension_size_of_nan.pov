// error: 4:14: dimension_size()'s dimension must be a finite number
// (issue 17, the reliability cases) once: read past the array's dimensions, silently.
#declare A = array[3];
#declare X = dimension_size(A, sqrt(-1));

