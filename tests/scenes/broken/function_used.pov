// error: 5:13: which hexant does not support
#declare F = function { transform { scale 2 } }
// A declaration that uses F is kept as source too; the sphere uses F itself.
#declare G = F(1, 0, 0);
sphere { 0, F(1, 0, 0) }
