// error: 4:14: changes more than 10000 times
// flags: --frame-count 10
// str() of clock to six places: 10^6 texts over the animation.
#declare S = str(clock, 0, 6);
