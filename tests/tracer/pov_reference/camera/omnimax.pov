// An omnimax camera looking up at the ring, its view turning with clock
// (the default right and up: the dome's 4:3 shift).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "camera_scene.inc"
camera { omnimax location <0, 0.5, 0> look_at <0, 0.8, 3> rotate y * 40 * clock }
