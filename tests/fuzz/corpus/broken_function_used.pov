// error: 5:13: which hexant does not support
#declare F = function(x) { x * 2 }
// A declaration that uses F is kept as source too; the sphere uses F itself.
#declare G = F(1);
sphere { 0, F(1) }

