// error: 3:14: argument 1 of bitwise_and() 1.0000000000000001e+300 is out of range: beyond 2^53
// (issue 17, the reliability cases) once: 1e300 cast to long long.
#declare B = bitwise_and(1e300, 1);

