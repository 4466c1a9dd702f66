// error: 6:8: nested more than 200 deep
// flags: --frame-count 10
// A #while on clock turns on the pieces of time where its condition holds,
// each turn a split inside the last: near clock 0 this one never ends.
#declare I = 0;
#while (I < 1 / clock)
  #declare I = I + 1;
#end
