// error: 2:10: expected a name to declare
#declare sphere = 1;

