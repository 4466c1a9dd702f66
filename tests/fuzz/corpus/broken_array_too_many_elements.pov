// error: 3:14: but 3 were given
// povray: line 3: Parse Error: No matching } in '{', float function 'float constant' found instead
#declare A = array[2] { 1, 2, 3 }

