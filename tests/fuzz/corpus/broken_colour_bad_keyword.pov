// error: 2:26: found 'purple'
#declare C = color red 1 purple 2;

