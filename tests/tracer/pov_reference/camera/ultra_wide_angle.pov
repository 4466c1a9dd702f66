// An ultra_wide_angle camera past 180 degrees, its angle and view turning
// with clock; up longer than right, so POV-Ray's aspect ratio scales the
// vertical angle.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "camera_scene.inc"
camera { ultra_wide_angle location <0, 1, 0> look_at <1, 0.2, 3> right x up 0.9 * y
         angle 200 - 60 * clock rotate y * 30 * clock }
