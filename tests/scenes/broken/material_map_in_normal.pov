// error: 4:42: material_map opens a texture and comes first in it: texture { material_map { TYPE "FILE" texture { } ... } }
// povray: line 4: Parse Error: No matching } in 'normal', material_map found
// (material_map picks whole textures: only a texture holds one.)
sphere { 0, 1 pigment { rgb 1 } normal { material_map } }
