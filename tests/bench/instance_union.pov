// instance_union.pov: a union of 2 N^2 still triangles (a wavy sheet)
// under one moving transform, issue 43's case from real animations, or the
// same triangles as one mesh (--declare AS_MESH=1). Renders with instances
// (the default), with --no-instances (each triangle an object of the
// hierarchy), or as a mesh; docs/benchmarks.md, "Instances":
//   build/hexant render tests/bench/instance_union.pov --declare N=108 \
//       -W 160 -H 120 --frame-count 16 --spp 4 --stats [--no-instances]
#version 3.7;
#ifndef (N) #declare N = 100; #end
#ifndef (AS_MESH) #declare AS_MESH = 0; #end
camera { location <0, 3, -6> look_at <0, 0, 0> angle 50 }
light_source { <-10, 20, -15>, rgb 1 }
background { rgb 0.1 }
plane { y, -1.5 pigment { checker rgb 0.8, rgb 0.4 } }
#macro Surface()
  #local I = 0;
  #while (I < N)
    #local J = 0;
    #while (J < N)
      #local X0 = -2 + 4 * I / N; #local X1 = -2 + 4 * (I + 1) / N;
      #local Z0 = -2 + 4 * J / N; #local Z1 = -2 + 4 * (J + 1) / N;
      #local Y00 = 0.3 * sin(3 * X0) * cos(3 * Z0); #local Y10 = 0.3 * sin(3 * X1) * cos(3 * Z0);
      #local Y01 = 0.3 * sin(3 * X0) * cos(3 * Z1); #local Y11 = 0.3 * sin(3 * X1) * cos(3 * Z1);
      triangle { <X0, Y00, Z0>, <X1, Y10, Z0>, <X1, Y11, Z1> }
      triangle { <X0, Y00, Z0>, <X1, Y11, Z1>, <X0, Y01, Z1> }
      #local J = J + 1;
    #end
    #local I = I + 1;
  #end
#end
#if (AS_MESH)
  mesh { Surface() pigment { rgb <0.9, 0.5, 0.2> } rotate y * 90 * clock translate x * clock }
#else
  union { Surface() pigment { rgb <0.9, 0.5, 0.2> } rotate y * 90 * clock translate x * clock }
#end
