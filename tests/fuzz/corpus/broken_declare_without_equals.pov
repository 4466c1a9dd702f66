// error: 2:12: expected '='
#declare X 1;

