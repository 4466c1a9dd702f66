// A shadowless light (POV-Ray's fill light) lights surfaces but no media:
// POV-Ray 3.7's ComputeOneMediaLightInterval takes point, spot and
// cylinder lights only. A box of scattering media lit by a shadowless
// light and by a spotlight turning with clock.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1.5, -6> look_at <0, 1, 0> angle 55 }
light_source { <6, 12, -4> rgb 1.5 shadowless }
light_source { <-4, 8, -3> rgb <1, 0.8, 0.6> spotlight radius 8 falloff 14
               point_at <-0.5 + clock, 0.5, 0> }
background { rgb <0.1, 0.1, 0.2> }
plane { y, -0.02 pigment { checker rgb 0.9 rgb 0.5 } }
box { <-2, 0, -1>, <1.5, 2, 1> hollow pigment { rgbf 1 }
      interior { media { method 3 samples 4 intervals 1 scattering { 1, rgb 0.25 } } } }
