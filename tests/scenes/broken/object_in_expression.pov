// error: 4:19: expected a scene item
// povray: line 4: Parse Error: Expected 'object or directive', + found instead
#declare Ball = sphere { 0, 1 }
#declare X = Ball + 1;
