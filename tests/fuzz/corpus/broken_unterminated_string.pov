// error: 2:18: unterminated string
#declare A = "abc
sphere { 0, 1 }

