// An #if on clock switching more often than --max-time-pieces (10^4) over
// the animation: read frame by frame, each frame at its opening clock.
// flags: --frame-count 10
#if (sin(clock * 100000) > 0)
  sphere { 0, 1 }
#end
