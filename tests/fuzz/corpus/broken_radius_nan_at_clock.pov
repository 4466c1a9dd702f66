// error: 4:1: the sphere's radius is NaN (not a number) at clock = 0.5
// flags: --frame-count 5
// Fine for the first half of the animation, NaN once clock passes 0.5.
sphere { 0, sqrt(1 - 2 * clock) }

