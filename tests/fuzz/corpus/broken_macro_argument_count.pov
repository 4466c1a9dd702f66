// error: 3:14: takes 1 argument, not 2
#macro Twice(V) (2 * V) #end
#declare B = Twice(1, 2);

