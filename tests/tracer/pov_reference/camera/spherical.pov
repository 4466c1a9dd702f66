// A spherical camera, its horizontal and vertical angles moving with clock.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "camera_scene.inc"
camera { spherical angle 360 - 60 * clock, 180 - 40 * clock location <0, 0.5, 0> look_at <0, 0.5, 1> }
