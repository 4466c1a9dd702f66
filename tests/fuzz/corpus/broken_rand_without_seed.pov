// error: 3:14: rand() needs a stream made by seed()
// (issue 17, the reliability cases) once: segfaulted: a NaN stream and no seed().
#declare X = rand(sqrt(-1));

