// error: 2:7: expected a loop variable name
#for (1, 2, 3)
#end

