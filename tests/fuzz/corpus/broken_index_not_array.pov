// error: 4:15: needs an array
// povray: line 4: Parse Error: All #declares of float, vector, and color require semi-colon ';' at end ... (it reads X, then stops at '[')
#declare X = 1;
#declare Y = X[0];

