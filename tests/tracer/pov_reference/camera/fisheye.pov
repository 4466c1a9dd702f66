// A fisheye looking down from above, its angle widening with clock.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "camera_scene.inc"
camera { fisheye location <0, 1.5, 0> look_at <0.01, -1, 1> angle 160 + 40 * clock }
