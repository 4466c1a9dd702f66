// error: 2:1: #switch has no matching #end
#switch (1)
  #case (1)
    sphere { 0, 1 }
  #break

