// error: 3:5: must be a float
// povray: line 3: Parse Error: Expected 'string comparison operator', ) found instead
#if ("a")
#end

