// error: 4:1: no matching #end
// povray: line 5: Parse Error: End of file reached but #end expected.
#declare I = 0;
#while (I < 3)
  #declare I = I + 1;

