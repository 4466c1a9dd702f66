// error: 3:15: not a string
// povray: line 3: Parse Error: Expected 'numeric expression', string literal found instead
sphere { 0, 1 rotate "x" }

