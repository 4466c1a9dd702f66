// Fuzz seed: text in POV-Ray's four fonts (Debian's fonts-povray), by
// name and as internal fonts, in both charsets, with kerning pairs,
// offsets, a negative thickness and a string of clock.
global_settings { charset utf8 }
camera { location <0, 0.5, -6> look_at <1.5, 0.5, 0> }
light_source { <-3, 5, -4> rgb 1 }
text { ttf "timrom.ttf" "AVAWToTy 0123", 0.3, <0.05, 0, 0> pigment { rgb 1 } translate <-2, 1, 0> }
text { ttf "cyrvetic.ttf" "\u00e9t\u00e9 ~", 0.2, 0 pigment { rgb x } translate <-2, 0, 0> }
text { ttf "crystal" concat("t=", str(clock, 0, 2)), clock, <0, 0.1, 0> pigment { rgb y } }
text { internal 0 "P", -0.1, 0 pigment { rgb z } translate <2, 0, 0> }
text { ttf "povlogo.ttf" "P", 1, 0 pigment { rgb 1 } translate <3, 1, 0> }
#declare E = text { internal 3 "Hex", 0.5, 0 }
object { E translate -max_extent(E) pigment { rgb 0.5 } }
