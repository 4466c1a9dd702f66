// error: 3:19: array size
// povray: line 3: Parse Error: Invalid dimension size for an array
#declare A = array[-1];

