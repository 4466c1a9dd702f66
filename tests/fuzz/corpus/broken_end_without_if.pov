// error: 3:1: expected a scene item
sphere { 0, 1 }
#end

