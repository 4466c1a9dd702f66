// error: 4:1: ';'
// povray: line 4: Parse Error: All #declares of float, vector, and color require semi-colon ';' at end if the language version is set to 3.5 or higher.
#declare Radius = 1
sphere { 0, Radius }
