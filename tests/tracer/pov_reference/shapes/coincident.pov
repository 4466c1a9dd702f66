// coincident: surfaces that lie exactly on each other. Which one POV-Ray
// shows depends on the order its bounding hierarchy meets them; in this
// scene (two spheres, a union of two, five nested unions of two, three
// spheres) it is the one written first everywhere, which is hexant's rule
// in every mode (tracer/object_test.hpp): before it, the walk's order
// picked, pixel by pixel. tests/tracer/pov_reference_test.cpp compares
// hexant's stills in its three modes with POV-Ray 3.7's.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -6> look_at <0, 0, 0> angle 50 }
light_source { <-3, 6, -5>, rgb 1 }
sphere { <-2, 1, 0>, 0.4 pigment { rgb <1, 0, 0> } }
sphere { <-2, 1, 0>, 0.4 pigment { rgb <0, 0, 1> } }
union {
  sphere { <0, 1, 0>, 0.4 pigment { rgb <1, 0.5, 0> } }
  sphere { <0, 1, 0>, 0.4 pigment { rgb <0, 0, 1> } }
}
union {
#declare I = 0;
#while (I < 5)
  union {
    sphere { <-2 + I, -1, 0>, 0.3 pigment { rgb <1, 0, 0.5> } }
    sphere { <-2 + I, -1, 0>, 0.3 pigment { rgb <0, 0, 1> } }
  }
  #declare I = I + 1;
#end
}
sphere { <2, 1, 0>, 0.4 pigment { rgb <1, 1, 0> } }
sphere { <2, 1, 0>, 0.4 pigment { rgb <0, 1, 0> } }
sphere { <2, 1, 0>, 0.4 pigment { rgb <0, 0, 1> } }
