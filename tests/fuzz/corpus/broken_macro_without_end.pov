// error: 2:1: #macro has no matching #end
#macro Ball(P)
  sphere { P, 1 }

