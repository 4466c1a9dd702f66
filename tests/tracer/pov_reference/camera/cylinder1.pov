// Cylinder camera 1: its angle widening with clock and the view turning
// (types 3 and 4 slide the eye along the axis: parallel rays that way).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "camera_scene.inc"
camera { cylinder 1 location <0, 1, -1> look_at <0, 0.5, 3> right 1.2 * x up 1.5 * y
         angle 120 + 90 * clock rotate y * 25 * clock }
