// error: include/bad_in_macro.inc:3:10: must be a float
// povray: file 'include/bad_in_macro.inc' line 3: Parse Error: Float expected but vector or color expression found.
#macro Load(Name)
#end
Load("include/bad_in_macro.inc")
// note: 4:3: included from here
// note: 6:1: in macro

