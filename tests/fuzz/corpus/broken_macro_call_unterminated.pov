// error: 5:1: expected ',' or ')'
// povray: line 4: Parse Error: Expected ')', End of File found instead
#macro Ball(P, R) sphere { P, R } #end
Ball(<0, 0, 0>, 1

