// error: 3:1: '#case'
// povray: line 3: Parse Error: Mis-matched '#case' or '#range'.
#case (1)
  sphere { 0, 1 }

