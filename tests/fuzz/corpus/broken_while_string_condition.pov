// error: 3:8: must be a float
// povray: line 3: Parse Error: Expected 'string comparison operator', ) found instead
#while ("yes")
#end

