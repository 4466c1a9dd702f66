// An orthographic camera: the view as wide at look_at as the perspective
// one at angle 50 (POV-Ray's resizing), turning and closing in with clock.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "camera_scene.inc"
camera { orthographic location <0, 6 - 2 * clock, -9> look_at <0, 0, 0> angle 50 - 10 * clock
         rotate y * 30 * clock }
