// error: 3:14: expected a value
// povray: line 3: Parse Error: Expected 'RValue to declare', ; found instead
#declare X = ;

