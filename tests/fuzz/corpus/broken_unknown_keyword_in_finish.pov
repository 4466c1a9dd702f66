// error: 3:34: found 'shiny'
// povray: line 3: Parse Error: No matching } in 'finish', undeclared identifier 'shiny' found instead
sphere { 0, 1 finish { phong 0.5 shiny 1 } }

