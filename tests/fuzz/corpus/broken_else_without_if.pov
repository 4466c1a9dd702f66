// error: 4:1: '#else'
// povray: line 4: Parse Error: Mis-matched '#else'.
sphere { 0, 1 }
#else
sphere { 0, 2 }

