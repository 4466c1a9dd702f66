// error: 3:22: to close the vector
// povray: line 3: Parse Error: Expected '>', ; found instead
#declare V = <1, 2, 3;

