// texture_edit: a pigment { } or normal { } that edits a texture comes
// after the transforms the texture has had (POV-Ray moves a plain
// texture's pigment and normal, and keeps no transform of its own): a
// declared layered texture turned, then its top layer's pigment turned
// again; an object's texture scaled with the object, then its pigment and
// normal edited; one of them turning with clock. Made after the
// distribution's ballbox1.pov (T_Stone1 { pigment { rotate 90*z } }).
// tests/tracer/pov_reference_test.cpp compares hexant's stills with
// POV-Ray 3.7's.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -5> look_at <0, 0.3, 0> angle 55 }
light_source { <-3, 8, -6> rgb 1 }
background { rgb 0.1 }
#declare Under = texture { pigment { gradient x color_map { [0 rgb <1, 0.2, 0>] [1 rgb <0, 0.4, 1>] } } }
#declare Over = texture { pigment { checker rgbt <1, 1, 1, 0> rgbt <0, 0, 0, 1> scale 0.25 } }
#declare Layered = texture { Under scale <2, 1, 1> rotate z * 40 } texture { Over scale <1, 3, 1> rotate z * -30 }
plane { y, -0.5 texture { Layered pigment { rotate y * (90 + 60 * clock) } } }
sphere { <-1.2, 0.6, 0.5>, 0.8
  texture { Layered rotate x * 20 pigment { scale 0.5 } normal { bumps 0.6 scale 0.2 } } }
sphere { <1.3, 0.6, 0.3>, 0.8
  texture { pigment { gradient y color_map { [0 rgb 1] [1 rgb <0.2, 0.8, 0.2>] } }
    normal { ripples 0.8 } }
  scale <1, 0.5, 1>
  pigment { rotate z * 45 } normal { scale 0.3 }
  translate y * 0.2 }
