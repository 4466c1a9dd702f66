// Declarations of things hexant lacks cost nothing while nothing uses them.
#declare F = function(x, y) { x * y }
#declare G = F(1, 2);                  // uses F: kept as source too
#declare Stone = pigment { marble turbulence 0.5 color_map { [0 rgb 0] [1 rgb 1] } }
#declare Blob = isosurface { function { x } }
#declare Layered = texture { pigment { rgb 1 } } texture { pigment { rgbt 1 } }
#declare Glass = material { texture { pigment { rgbt 1 } } interior { ior 1.5 } }
sphere { 0, 1 }
