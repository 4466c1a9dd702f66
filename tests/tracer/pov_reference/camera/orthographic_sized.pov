// An orthographic camera whose film is given by right and up (no resize).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "camera_scene.inc"
camera { orthographic location <0, 2, -9> right x * (12 - 4 * clock) up y * 9 look_at <0, 0, 0> }
