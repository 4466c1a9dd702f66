// text in two fonts, one string from str(clock): against POV-Ray 3.7
// (tests/tracer/pov_reference_test.cpp renders it at clock 0 and 0.5).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <1.7, 0.3, -4.4> look_at <1.7, 0.25, 0> angle 52 }
light_source { <3, 5, -6> color rgb 1 }
light_source { <-4, 2, -3> color rgb 0.4 }
background { color rgb <0.1, 0.1, 0.3> }
// The string changes with clock: "t = 0.00" at 0, "t = 0.50" at 0.5.
text { ttf "timrom.ttf" concat("t = ", str(clock, 0, 2)), 0.3, 0
  pigment { color rgb <1, 0.8, 0.2> } finish { phong 0.4 }
  translate <0, 0.55, 0> }
// A second font, kerned pairs (AV, Wa), an offset and a turn with clock.
text { ttf "cyrvetic.ttf" "AVATAR Wave", 0.2, <0.03, 0.01, 0>
  pigment { checker color rgb <0.3, 0.9, 0.5> color rgb <0.1, 0.4, 0.8> scale 0.1 }
  scale 0.55 rotate y*(-25 + 50*clock) translate <0, -0.35, 0> }
plane { y, -0.5 pigment { color rgb 0.6 } }
// Glyphs 200 units from the text's own origin (800 spaces first), brought
// back by a translate and turned: their faces must not shadow themselves.
#declare Far = ""; #for (I, 1, 800) #declare Far = concat(Far, " "); #end
text { ttf "timrom.ttf" concat(Far, "31o"), 0.3, 0
  pigment { color rgb <1, 0.6, 0.2> } finish { ambient 0.2 diffuse 0.8 }
  translate <-204.694 + 3.5, 0, 0> rotate y * -30 scale 0.5 translate <2.2, -0.45, -0.6> }
