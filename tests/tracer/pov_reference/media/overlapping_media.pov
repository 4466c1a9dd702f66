// Two hollow boxes of scattering media that overlap, the second sliding
// with clock, and a non-hollow glass ball in the first. The light that a
// media sample (or the floor) receives is dimmed, between each pair of
// surfaces its shadow ray crosses, by the media of every interior it is
// in then (POV-Ray 3.7's ComputeShadowColour and ComputeShadowMedia: the
// shadow ray starts with the viewing ray's interiors and goes in or out
// of each object it meets), not only by the one it leaves.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 5 }
camera { location <0, 1.5, -6> look_at <0, 1, 0> angle 55 }
light_source { <6, 12, -4> rgb 2 }
background { rgb <0.1, 0.1, 0.2> }
plane { y, -0.02 pigment { checker rgb 0.9 rgb 0.5 } }
box { <-2, 0, -1>, <1, 2, 1> hollow pigment { rgbf 1 }
      interior { media { method 3 samples 4 intervals 1 scattering { 2, rgb 0.25 extinction 1 } } } }
box { <-1, 0.5, -0.5>, <2, 2.5, 1.5> hollow pigment { rgbf 1 }
      interior { media { method 3 samples 2 intervals 1
                         scattering { 4, rgb <0.25, 0.6, 0.9> * 0.4 extinction 1 } } }
      translate <0.4 * clock, 0, 0> }
sphere { <-1.3, 1, 0>, 0.4 pigment { rgbf <1, 1, 1, 0.9> } interior { ior 1.3 } }
