// error: 3:8: cone needs
// povray: line 3: Parse Error: Expected 'numeric expression', } found instead
cone { <0, 0, 0>, 1, <0, 1, 0> }

