// error: 7:3: more than 100000 loop iterations and macro calls in all
// flags: --max-iterations 100000
// Each loop stays under the per-loop limit; together they would take 10^10 steps.
#declare I = 0;
#while (I < 100000)
  #declare J = 0;
  #while (J < 100000)
    #declare J = J + 1;
  #end
  #declare I = I + 1;
#end

