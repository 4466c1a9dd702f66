// error: 4:3: parameter name
// povray: line 4: Parse Error: Expected 'identifier or expression.', sphere found instead
#macro Ball(P, R
  sphere { P, R }
#end

