// error: 8:12: this text has 16777216 characters, each glyph an object
// (issue 45) once: a text of 16 Mi characters took 12 GB in 60 s. Its
// characters are counted before its glyphs are laid out.
camera { location <0, 0, -5> look_at 0 }
light_source { <5, 5, -5> color rgb 1 }
#declare S = "ab";
#for (I, 1, 23) #declare S = concat(S, S); #end
text { ttf "timrom.ttf" S 0.1, 0 pigment { rgb 1 } }
