// error: 2:16: cannot apply '+' to float and string
#declare X = 1 + "a";

