// error: 5:26: a patterned texture (texture_map, material_map, tiles, a block pattern's textures) takes no finish of its own, as in POV-Ray: give it to each of its textures
// povray: line 5: Parse Error: No matching } in 'texture', finish found
// (A declared checker of textures, then a finish: POV-Ray reads a finish only in a plain texture.)
#declare M = texture { checker texture { pigment { rgb x } } texture { pigment { rgb y } } }
plane { z, 0 texture { M finish { ambient 1 } } }
