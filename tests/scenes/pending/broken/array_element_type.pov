// error: 5:17: float
// povray: line 5: Parse Error: Attempted to redefine float identifier as vector identifier.
#declare A = array[2];
#declare A[0] = 1;
#declare A[1] = <1, 2, 3>;
