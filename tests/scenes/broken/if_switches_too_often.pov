// error: 5:5: changes more than 10000 times
// flags: --frame-count 10
// An #if on clock splits time where its condition changes
// (language/time_branch.hpp), up to --max-time-pieces (10^4) switches.
#if (sin(clock * 100000) > 0)
  sphere { 0, 1 }
#end
