// A fuzz find, reduced by hand (tests/fuzz/ 2026-11-30): a box 10^308 long
// and 3 high among a few small ones. Halving every axis of every cell made
// cells 2^-24 of the height at depth 24, and a ray rising through the
// height crossed 2^24 of them: over 100 s and gigabytes for an 8 by 8
// frame. Now a space split halves only the axes at least half as wide as
// the widest (tracer/hierarchy.cpp, split_axes).
camera { location <0, 1, -6> look_at <0, 1, 0> }
light_source { <-5, 9, -7>, rgb 1 }
plane { y, 0 pigment { rgb 0.8 } }
box { <-1e308, 0, -1e308>, <1e308, 3, 0.45> pigment { rgb <0.3, 0.5, 0.9> } }
#for (I, 0, 7)
  box { <-5.45 + I, 0, -8.45>, <0.45 + I, 3, 0.45> pigment { rgb 1 } }
#end
