// error: 3:25: undeclared identifier 'Spin'
// povray: line 3: Parse Error: Missing { after 'undeclared identifier', undeclared identifier 'Spin' found instead
sphere { 0, 1 transform Spin }

