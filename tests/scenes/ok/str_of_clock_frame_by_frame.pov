// str() of clock to six places: 10^6 texts over the animation, more than
// --max-time-pieces: read frame by frame, each frame at its opening clock.
// flags: --frame-count 10
#declare S = str(clock, 0, 6);
