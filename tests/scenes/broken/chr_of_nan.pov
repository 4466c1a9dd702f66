// error: 3:14: chr()'s character code must be a finite number
// (issue 17, the reliability cases) once: a NaN code passed the range test.
#declare C = chr(sqrt(-1));
