// error: 3:25: not a string
// povray: line 3: Parse Error: Expected 'string comparison operator', } found instead
sphere { 0, 1 pigment { rgb "red" } }

