// error: 3:5: expected '('
// povray: line 3: Parse Error: Expected '(', float function 'float constant' found instead
#if 1
#end

