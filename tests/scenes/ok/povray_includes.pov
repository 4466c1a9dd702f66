// needs: povray-includes
// flags: -L /usr/share/povray-3.7/include
// POV-Ray's own include files load: their unused functions, patterns and
// object kinds cost nothing.
#include "colors.inc"
#include "math.inc"
#include "transforms.inc"
#include "shapes.inc"
#include "textures.inc"
#include "metals.inc"
#include "woods.inc"
sphere { 0, 1 pigment { Orange } transform { Reorient_Trans(x, y) } }
object { Cube scale 0.5 pigment { Gray50 } }
