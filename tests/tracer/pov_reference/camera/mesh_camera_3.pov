// A mesh camera of distribution 3 (texture baking): a pixel's (u, v) finds
// the face of the mesh whose uv triangle holds it, and the ray leaves the
// point there along the face's normal (smooth: the vertex normals
// interpolated). The mesh is a half cylinder looking inwards, its uv the
// unrolled surface, so the image is a wide view around the objects inside.
// The camera direction's negative z turns the rays around (inwards).
#version 3.7;
global_settings { assumed_gamma 1 }
#declare N = 24;
#declare R = 4;
#declare Wall = mesh2 {
      vertex_vectors { 2 * (N + 1),
        #for (K, 0, N) #local A = radians(-90 + 180 * K / N);
          <R * sin(A), -1.5, R * cos(A)>, <R * sin(A), 1.5, R * cos(A)>
        #end
      }
      normal_vectors { 2 * (N + 1),
        #for (K, 0, N) #local A = radians(-90 + 180 * K / N);
          <sin(A), 0, cos(A)>, <sin(A), 0, cos(A)>
        #end
      }
      uv_vectors { 2 * (N + 1),
        #for (K, 0, N) <K / N, 0>, <K / N, 1> #end
      }
      face_indices { 2 * N,
        #for (K, 0, N - 1) <2 * K, 2 * K + 2, 2 * K + 1>, <2 * K + 1, 2 * K + 2, 2 * K + 3> #end
      }
}
camera {
  mesh_camera { 1 3
    mesh { Wall translate <0, 0.5, 0> }
    smooth
  }
  location <0, 0, 0.2>
  direction <0, 0, -1>
}
light_source { <-3, 5, -2> rgb 1 }
sphere { <-1, 0, 1>, 0.8 pigment { rgb <1, 0.3, 0.2> } finish { phong 0.6 } }
cone { <1, -1, 0.5>, 0.7, <1, 1, 0.5>, 0 pigment { rgb <0.3, 0.9, 0.3> } }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.1 } }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.6, 0.7, 1>] [1 rgb <0.1, 0.2, 0.6>] } } }
