// A ray that passes straight through a surface (the same ior on both
// sides: clear objects with no ior, or the overlap of a glass union left)
// goes on at the same trace level, as POV-Ray 3.7 continues it (TraceRay's
// continuedRay): under max_trace_level 3 the far ones of a row of clear
// balls (sliding with clock) and the glass behind them still show.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 3 }
camera { location <0, 0.6, -5> look_at <0, 0.5, 0> angle 45 }
light_source { <3, 6, -4> rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
plane { y, -0.5 pigment { checker rgb <1, 0.5, 0.3> rgb <0.3, 0.4, 0.9> } }
#for (i, 0, 4)
sphere { <0.25 * i - 0.6 + 0.3 * clock, 0.5, i * 0.8>, 0.6
         pigment { rgbf <1, 0.95 - 0.05 * i, 0.85, 0.92> } finish { specular 0.5 } }
#end
union {
  sphere { <-0.3, 0, 0>, 0.5 }
  sphere { <0.3, 0, 0>, 0.5 }
  pigment { rgbf <0.9, 1, 0.9, 0.9> } interior { ior 1.4 }
  translate <1.2, 0.4, 5>
}
