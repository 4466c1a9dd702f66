// error: 4:4: #error: this scene needs Wanted = 3
#declare Wanted = 2;
#if (Wanted != 3)
  #error "this scene needs Wanted = 3"
#end

