// Seed: branches on clock (language/time_branch.hpp) of every kind.
camera { location <0, 2, -8> look_at <0, 1, 0> }
#if (clock < 0.5) camera { location <2, 2, -8> look_at 0 } #end
#if (frame_number > 2) background { rgb <0.1, 0.2, 0.3> } #end
light_source { <-4, 8, -6>, rgb 1 }
#if (sin(2 * pi * clock) > 0.5) light_source { <4, 3, -6>, rgb 0.5 } #end
#macro Hop(T) #if (T < 0.5) (cos(pi * T)) #else (-cos(pi * T)) #end #end
#declare V = 1;
#if (clock > 0.7) #undef V #end
#ifdef (V) sphere { <0, Hop(clock), 0>, V } #end
#declare I = 0;
#while (I < clock * 6)
  #if (mod(floor(clock * 8), 2) = 1) sphere { <I, 0.3, 0>, 0.3 } #else box { <I, 0, 0>, <I + 0.5, 0.5, 0.5> } #end
  #declare I = I + 1;
#end
#for (J, 1, clock * 3) cylinder { <-J, 0, 0>, <-J, 1, 0>, 0.2 } #end
#switch (clock)
  #range (0, 0.25) torus { 1, 0.2 } #break
  #case (0.5) disc { 0, y, 1 } #break
  #else cone { 0, 1, y, 0 }
#end
#declare Sizes = array[3] { 0.1, 0.2, 0.3 }
sphere { <0, 3, 0>, Sizes[min(clock * 3, 2)] }
union { #if (clock > 0.2) sphere { 0, 1 } #end box { -0.5, 0.5 } translate <3, 0, 2> }
difference { #if (clock > 0.5) box { -1, 1 } #end sphere { <0, 0, -1>, 0.7 } translate <-3, 0, 2> }
intersection { sphere { 0, 1.5 } #if (clock < 0.5) box { <-2, 0, -2>, <2, 2, 2> } #end translate <0, 0, 4> }
sphere { vnormalize(<clock - 0.5, 0, 0>), 0.1 }
