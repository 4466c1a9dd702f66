// error: 4:1: #for needs finite bounds and step
// (issue 45) once: a NaN end ran no turn with exit 0, where every other NaN is an error at its place.
#declare E = sqrt(-1);
#for (I, 0, E) sphere { 0, 1 } #end
