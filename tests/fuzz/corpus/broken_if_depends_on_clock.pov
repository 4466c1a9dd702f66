// error: 3:5: depends on clock
// flags: --frame-count 10
#if (clock > 0.5)
  sphere { 0, 1 }
#end

