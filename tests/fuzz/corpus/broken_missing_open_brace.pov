// error: 3:8: expected '{'
// povray: line 3: Parse Error: Missing { after 'sphere', float function 'float constant' found instead
sphere 0, 1 }

