// error: 3:1: 'Ball'
// povray: line 3: Parse Error: Expected 'object or directive', undeclared identifier 'Ball' found instead
Ball(<0, 0, 0>, 1)

