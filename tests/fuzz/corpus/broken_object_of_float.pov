// error: 4:10: needs an object
// povray: line 4: Parse Error: Expected 'object', float function 'float identifier' found instead
#declare Three = 3;
object { Three }

