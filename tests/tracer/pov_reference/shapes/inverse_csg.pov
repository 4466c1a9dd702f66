// Inverted CSG as POV-Ray 3.7 inverts it (Invert_CSG_Object): an inverted
// union is the intersection of its members inverted, so the surfaces of a
// member inside another are gone; qtvrpanorama's hollow box, the camera
// inside it looking out through the holes the inverted cylinder clusters
// cut, the clusters turning with clock. Beside it an inverted
// intersection (the merge of its members inverted) cut from a box.
#version 3.6;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, 0> look_at <0.3, 0.2, 1> angle 100 }
light_source { <-100, 50, -50> rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.2, 0.2, 1>] [1 rgb 1] } } }
#declare CylinderCluster = union {
  cylinder { -z, +z, 1 }
  cylinder { -z, +z, 1 translate -x-y }
  cylinder { -z, +z, 1 translate +x-y }
  cylinder { -z, +z, 1 translate -x+y }
  cylinder { -z, +z, 1 translate +x+y }
  scale <0.4, 0.4, 1.1>
  rotate z * 20 * clock
}
intersection {
  box { -1, +1 }
  object { CylinderCluster inverse }
  object { CylinderCluster rotate 90*y inverse }
  object { CylinderCluster rotate 90*x inverse }
  pigment { rgb <1, 0.5, 0.2> }
}
intersection {
  box { -0.6, 0.6 }
  object { intersection { sphere { -0.2*x, 0.5 } sphere { 0.2*x, 0.5 } } inverse }
  rotate y * 30 translate <2.2, -1, 3>
  pigment { rgb <0.3, 0.9, 0.4> }
}
plane { y, -3 pigment { checker rgb 1 rgb 0 } }
