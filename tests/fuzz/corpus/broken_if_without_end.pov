// error: 2:1: #if has no matching #end
#if (1)
  sphere { 0, 1 }

