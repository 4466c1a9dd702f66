// error: 3:14: rand() needs a stream made by seed()
// (issue 17, ../shared/cases/reliability) once: segfaulted: a NaN stream and no seed().
#declare X = rand(sqrt(-1));

