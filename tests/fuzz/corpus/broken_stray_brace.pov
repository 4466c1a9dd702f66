// error: 3:1: found '}'
sphere { 0, 1 }
}

