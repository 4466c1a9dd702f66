// error: 5:33: the scene ran more than 100000 loop iterations and macro calls
// flags: --max-iterations 100000
// (issue 45) once: Fibonacci of 40 ran six minutes under the former default
// of 10^8; it stops at 10^7 now (about 40 s on a loaded 2-core machine).
#macro F(N) #if (N < 2) N #else F(N - 1) + F(N - 2) #end #end
#declare X = F(40);
camera { location <0, 0, -5> look_at 0 }
sphere { 0, 1 pigment { rgb 1 } }
