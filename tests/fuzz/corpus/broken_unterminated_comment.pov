// error: 3:1: unterminated comment
sphere { 0, 1 }
/* never closed
sphere { 0, 1 }

