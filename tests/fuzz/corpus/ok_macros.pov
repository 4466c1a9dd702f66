// Macros: parameters, macros that return expressions (floats, vectors,
// colours), objects and textures, recursion, #local scope, arguments passed
// by reference, macros calling macros. Every result is checked with #error.
#version 3.7;
global_settings { assumed_gamma 1.0 }

#macro Square(A) (A * A) #end
#macro Mid(P, Q) ((P + Q) / 2) #end
#macro Grey(L) rgb L #end
#macro Factorial(N)           // recursive; the result goes through a #local
  #if (N <= 1)
    #local Result = 1;
  #else
    #local Result = N * Factorial(N - 1);
  #end
  Result
#end
#macro Bump(Counter)          // changes the caller's variable (by reference)
  #declare Counter = Counter + 1;
#end
#macro Hidden()
  #local Inner = 5;           // gone when the macro returns
  Inner * 2
#end
#macro Ball(Where, R)
  sphere { Where, R pigment { Grey(0.5) } }
#end
#macro Pair(Where)            // a macro calling a macro
  union { Ball(Where, 0.5) Ball(Where + x, 0.25) }
#end
#macro Paint(C) texture { pigment { C } finish { phong 0.5 } } #end

#if (Square(3) != 9)                  #error "Square" #end
#if (Square(1 + 1) != 4)              #error "macro argument is a value" #end
#if (2 * Square(2) + 1 != 9)          #error "macro result in an expression" #end
#declare M = Mid(<0, 0, 0>, <2, 4, 6>);
#if (M.x != 1 | M.y != 2 | M.z != 3)  #error "Mid" #end
#if (Factorial(5) != 120)             #error "Factorial" #end
#declare N = 1;
Bump(N)
Bump(N)
#if (N != 3)                          #error "by reference" #end
#declare H = Hidden();
#if (H != 10)                         #error "Hidden" #end
#ifdef (Inner)                        #error "#local leaked" #end
#declare G = Grey(0.25);
#if (G.green != 0.25)                 #error "Grey" #end

Ball(<0, 1, 0>, 1)
object { Pair(<2, 0, 0>) rotate 30 * y }
#declare Twin = Pair(<-2, 0, 0>)
object { Twin }
box { -1, 1 Paint(rgb <1, 0, 0>) translate 4 * z }

