// Control flow: #switch falls through to the next #case until #break (as in
// POV-Ray), #range, #else, nested loops, #for with negative and fractional
// steps, #if/#elseif chains, #ifdef/#ifndef and #undef. Checked with #error.
#version 3.7;
global_settings { assumed_gamma 1.0 }

#declare Trail = 0;
#switch (1)
  #case (1)
    #declare Trail = Trail + 1;
  #case (2)                    // no #break above: falls through
    #declare Trail = Trail + 10;
    #break
  #case (3)
    #declare Trail = Trail + 100;
#end
#if (Trail != 11) #error "fall-through" #end

#declare Picked = 0;
#switch (2.5)
  #case (1) #declare Picked = 1; #break
  #range (2, 3) #declare Picked = 2; #break
  #else #declare Picked = 3;
#end
#if (Picked != 2) #error "#range" #end
#switch (7)
  #case (1) #declare Picked = 1;
  #else #declare Picked = 4;
#end
#if (Picked != 4) #error "#else of #switch" #end

#declare Sum = 0;
#for (I, 10, 1, -3)            // 10, 7, 4, 1
  #declare Sum = Sum + I;
#end
#if (Sum != 22) #error "#for down" #end
#declare Steps = 0;
#for (F, 0, 1, 0.25)           // 0, .25, .5, .75, 1
  #declare Steps = Steps + 1;
#end
#if (Steps != 5) #error "#for by 0.25" #end

#declare Cells = 0;
#declare I = 0;
#while (I < 3)
  #declare J = 0;
  #while (J < 4)
    #switch (mod(I + J, 2))
      #case (0) #declare Cells = Cells + 1; #break
    #end
    #declare J = J + 1;
  #end
  #declare I = I + 1;
#end
#if (Cells != 6) #error "nested loops" #end

#declare Grade = 72;
#if (Grade >= 90)
  #declare Letter = "A";
#elseif (Grade >= 80)
  #declare Letter = "B";
#elseif (Grade >= 70)
  #declare Letter = "C";
#else
  #declare Letter = "F";
#end
#if (asc(Letter) != asc("C")) #error "#elseif" #end

#declare Temp = 1;
#ifdef (Temp) #undef Temp #end
#ifdef (Temp) #error "#undef" #end
#ifndef (Temp) #declare Temp = 2; #end
#if (Temp != 2) #error "#ifndef" #end
#if (0) #error "skipped text is not run" #end
#if (0)
  #if (1) #error "nested skipped #if" #end
  this text is skipped { and may be anything
#end
#debug concat("control_flow: ", Letter, "\n")
sphere { 0, 1 }

