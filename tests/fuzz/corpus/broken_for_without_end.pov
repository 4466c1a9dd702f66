// error: 3:1: no matching #end
// povray: line 4: Parse Error: End of file reached but #end expected.
#for (I, 1, 3)
  sphere { x * I, 0.5 }

