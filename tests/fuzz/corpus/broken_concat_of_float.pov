// error: 3:14: must be a string
// povray: line 3: Parse Error: Expected 'string expression', float function 'float constant' found instead
#declare S = concat("radius ", 1);

