// error: 2:15: malformed number
#declare X = 1e;

