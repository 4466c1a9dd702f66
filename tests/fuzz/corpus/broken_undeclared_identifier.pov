// error: 2:13: undeclared identifier 'Radius'
sphere { 0, Radius }

