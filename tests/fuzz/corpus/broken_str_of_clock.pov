// error: 3:14: depends on clock
// flags: --frame-count 10
#declare S = str(clock, 0, 2);

