// error: 8:3: the scene's meshes hold more than 1000 triangles
// flags: --max-triangles 1000
// (issue 45) once: a mesh of 10^7 triangles from a #for loop read for a
// minute, past 1 GB, without a word. The default is 4*10^6.
camera { location <0, 0, -5> look_at 0 }
mesh {
#for (I, 0, 2000)
  triangle { <I * 1e-3, 0, 0>, <I * 1e-3, 1, 0>, <I * 1e-3 + 1e-3, 0, 0> }
#end
  pigment { rgb 1 }
}
