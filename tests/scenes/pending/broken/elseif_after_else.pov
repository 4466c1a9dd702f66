// error: 7:1: #elseif
// povray: line 7: Parse Error: Mis-matched '#elseif'.
#if (0)
  sphere { 0, 1 }
#else
  sphere { 0, 2 }
#elseif (1)
  sphere { 0, 3 }
#end
