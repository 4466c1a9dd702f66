// error: 4:8: depends on clock
// flags: --frame-count 10
#declare I = 0;
#while (I < clock)
  #declare I = I + 1;
#end

