// error: 3:15: undeclared identifier 'Size'
#macro Ball(P)
  sphere { P, Size }
#end
Ball(<1, 0, 0>)
// note: 5:1: in macro 'Ball'

