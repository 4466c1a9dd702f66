// error: 3:25: checker takes at most 2 colours
// povray: line 3: Parse Error: No matching } in 'pigment', color keyword 'rgb' found instead
sphere { 0, 1 pigment { checker rgb 1, rgb 0, rgb 0.5 } }
