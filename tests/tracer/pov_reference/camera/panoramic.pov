// A panoramic camera in the middle of the ring, turning with clock.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "camera_scene.inc"
camera { panoramic location <0, 0.5, 0> look_at <0, 0.5, 1> right x * 1.33 up y rotate y * 60 * clock }
