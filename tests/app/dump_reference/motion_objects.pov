// Reference scene for `hexant dump`: objects whose parameters and transforms
// depend on clock. POV-Ray prints, with #debug, the values hexant's dump must
// show at the same clock: parameters directly, and transforms by where they
// take the points x, y and z (vtransform from transforms.inc).
#version 3.7;
#declare Centre = vrotate(3 * x, 360 * clock * z);
#declare Radius = 0.5 + 0.25 * sin(2 * pi * clock);
#declare Spin = transform { rotate y * 360 * 3 * clock translate <clock, 0, 1> scale 1 + clock }
sphere { Centre, Radius transform Spin }
#declare Base = <0, clock, 0>;
#declare Cap = <1, 2, 3> * (1 + clock);
cylinder { Base, Cap, 0.1 + clock }
// hexant runs this scene with --declare Hexant_Dump=1: its values depend on
// clock there, so it skips the printing (which POV-Ray does per frame).
#ifndef (Hexant_Dump)
#include "transforms.inc"
#macro Show(Name, V)
#debug concat(Name, " = ", vstr(3, V, ", ", 0, 10), "\n")
#end
Show("sphere.center", Centre)
#debug concat("sphere.radius = ", str(Radius, 0, 10), "\n")
Show("sphere.transform.origin", vtransform(<0, 0, 0>, Spin))
Show("sphere.transform.x", vtransform(x, Spin))
Show("sphere.transform.y", vtransform(y, Spin))
Show("sphere.transform.z", vtransform(z, Spin))
Show("cylinder.base", Base)
Show("cylinder.cap", Cap)
#debug concat("cylinder.radius = ", str(0.1 + clock, 0, 10), "\n")
#end
