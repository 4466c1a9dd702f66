// error: 3:8: macro's name
// povray: line 3: Parse Error: Expected 'undeclared identifier', sphere found instead
#macro sphere(A) A #end

