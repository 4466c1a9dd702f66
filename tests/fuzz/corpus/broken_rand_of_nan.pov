// error: 4:14: rand()'s stream (made by seed()) must be a finite number
// (issue 17, the reliability cases) once: a NaN stream index.
#declare S = seed(1);
#declare X = rand(sqrt(-1));

