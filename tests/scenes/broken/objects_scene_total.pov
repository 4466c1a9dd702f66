// error: 7:3: the scene would make more than 100 objects
// flags: --max-objects 100
// (issue 45) The scene's total: copies placed one by one count each.
camera { location <0, 0, -5> look_at 0 }
#declare U = union { sphere { 0, 1 } sphere { x, 1 } sphere { y, 1 } sphere { z, 1 } }
#for (I, 1, 30)
  object { U translate I * x }
#end
