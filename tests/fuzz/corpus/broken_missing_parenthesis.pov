// error: 3:30: expected ')'
// povray: line 3: Parse Error: Expected ')', ; found instead
#declare X = (1 + 2 * (3 - 1);

