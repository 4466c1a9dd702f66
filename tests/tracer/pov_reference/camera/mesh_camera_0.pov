// A mesh camera of distribution 0 (POV-Ray 3.7's mesh_camera): two flat
// mesh2s (declared: POV-Ray's mesh_camera takes mesh { } around them) of one triangle per pixel, in POV-Ray's face order (row by row from
// the top), whose rays run along +z; the second mesh lies a quarter pixel
// to the right, so each pixel averages two rays. The camera's location z
// moves the rays' origins along the faces' normals. The meshes turn with
// clock.
#version 3.7;
global_settings { assumed_gamma 1 }
#declare W = image_width;
#declare H = image_height;
#macro Film(Shift)
  mesh2 {
    vertex_vectors { W * H * 3,
      #for (J, 0, H - 1) #for (I, 0, W - 1)
        #local X0 = (I - W / 2 + Shift) / W * 4;
        #local Y0 = (H / 2 - J) / H * 3;
        <X0, Y0, 0>, <X0 + 4 / W, Y0, 0>, <X0, Y0 - 3 / H, 0>
      #end #end
    }
    face_indices { W * H,
      #for (F, 0, W * H - 1) <3 * F, 3 * F + 1, 3 * F + 2> #end
    }
  }
#end
#declare Film0 = Film(0);
#declare Film1 = Film(0.25);
camera {
  mesh_camera { 2 0
    mesh { Film0 rotate z * 10 * clock translate <0, 0, -4> }
    mesh { Film1 rotate z * 10 * clock translate <0, 0, -4> }
  }
  location <0, 0, 0.5>
}
light_source { <-3, 5, -6> rgb 1 }
sphere { <-0.8, 0, 1>, 1 pigment { rgb <1, 0.3, 0.2> } finish { phong 0.6 } }
box { <0.4, -1, 0>, <1.6, 0.4, 1.2> rotate y * 30 pigment { checker rgb 1 rgb <0.2, 0.4, 1> scale 0.3 } }
plane { z, 3 pigment { checker rgb 0.9 rgb 0.1 } }
