// Reference scene for hexant's interpreter tests: every #debug line is
// NAME = VALUE, floats printed with str(v, 0, 10). See README.md.
#version 3.7;
// Arrays, loops, #switch, #if and macros.

#declare A = array[4] {10, 20, 30, 40}
#debug concat("array_1 = ", str(A[1], 0, 10), "\n")
#debug concat("array_expr_index = ", str(A[1 + 2], 0, 10), "\n")
#declare A[2] = A[0] + A[3];
#debug concat("array_assigned = ", str(A[2], 0, 10), "\n")
#debug concat("array_size = ", str(dimension_size(A, 1), 0, 10), "\n")
#debug concat("array_dims = ", str(dimensions(A), 0, 10), "\n")
#declare M = array[2][3] { {1, 2, 3}, {4, 5, 6} }
#debug concat("matrix_1_2 = ", str(M[1][2], 0, 10), "\n")
#debug concat("matrix_size_1 = ", str(dimension_size(M, 1), 0, 10), "\n")
#debug concat("matrix_size_2 = ", str(dimension_size(M, 2), 0, 10), "\n")
#debug concat("matrix_dims = ", str(dimensions(M), 0, 10), "\n")
#declare Empty = array[3];
#declare Empty[1] = <1, 2, 3>;
#debug concat("array_vector_y = ", str(Empty[1].y, 0, 10), "\n")

#declare Sum = 0;
#for (I, 1, 10)
  #declare Sum = Sum + I;
#end
#debug concat("for_sum = ", str(Sum, 0, 10), "\n")
#debug concat("for_var_after = ", str(I, 0, 10), "\n")
#declare Sum = 0;
#for (I, 10, 0, -2.5)
  #declare Sum = Sum + I;
#end
#debug concat("for_step_sum = ", str(Sum, 0, 10), "\n")
#declare Count = 0;
#for (I, 1, 0)
  #declare Count = Count + 1;
#end
#debug concat("for_empty = ", str(Count, 0, 10), "\n")

#declare N = 1;
#declare Steps = 0;
#while (N < 1000)
  #declare N = N * 3;
  #declare Steps = Steps + 1;
#end
#debug concat("while_n = ", str(N, 0, 10), "\n")
#debug concat("while_steps = ", str(Steps, 0, 10), "\n")

#macro Classify(V)
  #switch (V)
    #case (0)
      #local R = 100;
    #break
    #case (1)
    #case (2)
      #local R = 200;
    #break
    #range (3, 5)
      #local R = 300;
    #break
    #else
      #local R = 400;
  #end
  R
#end
#debug concat("switch_0 = ", str(Classify(0), 0, 10), "\n")
#debug concat("switch_1 = ", str(Classify(1), 0, 10), "\n")
#debug concat("switch_2 = ", str(Classify(2), 0, 10), "\n")
#debug concat("switch_4 = ", str(Classify(4.5), 0, 10), "\n")
#debug concat("switch_9 = ", str(Classify(9), 0, 10), "\n")

#macro Sign(V)
  #if (V < 0)
    -1
  #elseif (V = 0)
    0
  #else
    1
  #end
#end
#debug concat("if_neg = ", str(Sign(-5), 0, 10), "\n")
#debug concat("if_zero = ", str(Sign(0), 0, 10), "\n")
#debug concat("if_pos = ", str(Sign(3), 0, 10), "\n")

#macro Factorial(K)
  #if (K <= 1)
    1
  #else
    K * Factorial(K - 1)
  #end
#end
#debug concat("macro_recursive = ", str(Factorial(6), 0, 10), "\n")

#macro Scale2(V) (2 * V) #end
#debug concat("macro_paren = ", str(Scale2(3) + 1, 0, 10), "\n")
#declare W = Scale2(<1, 2, 3>);
#debug concat("macro_vector.z = ", str(W.z, 0, 10), "\n")

#macro Bump(Var)
  #declare Var = Var + 1;
#end
#declare Counter = 5;
Bump(Counter)
#debug concat("macro_by_reference = ", str(Counter, 0, 10), "\n")

#declare G = 1;
#macro Shadow()
  #local G = 2;
  G * 10
#end
#debug concat("local_in_macro = ", str(Shadow(), 0, 10), "\n")
#debug concat("global_after = ", str(G, 0, 10), "\n")

#ifdef (G)
  #debug "ifdef_defined = 1\n"
#end
#ifndef (Undefined_Thing)
  #debug "ifndef_undefined = 1\n"
#end
#undef G
#ifdef (G)
  #debug "undef = 0\n"
#else
  #debug "undef = 1\n"
#end

