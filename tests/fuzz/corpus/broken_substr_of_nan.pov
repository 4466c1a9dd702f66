// error: 3:14: substr()'s start must be a finite number
// (issue 17, the reliability cases) once: a NaN start passed the range test.
#declare S = substr("abc", sqrt(-1), 1);

