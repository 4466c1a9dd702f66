// error: 2:14: sin() takes 1 argument
#declare B = sin(1, 2);

