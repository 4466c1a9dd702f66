// error: 3:1: '#break'
// povray: line 3: Parse Error: Invalid context for #break
#break
sphere { 0, 1 }

