// Found by the fuzzer on 2026-11-30 (a timeout): a cone twisted 8e18 degrees
// a unit and tapered 5e8 a unit, whose every curved-path search examines
// the 65,536 pieces of its limit without pruning (2 s for an 8x8 frame in
// the release build); the fuzzer now lowers the limit (tests/fuzz/).
// twister.pov: objects that deform while th{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{uaverageion{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{unio({union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{ column: a quarter turn per unit of height 1/0at the extremes of its
// swng, back to straight twice over the animation.
box {
    <-5.45, 0, -0.45>, <0.45, 3, 0.45>
    twist y, 90 * sin(3 * pi * clock)
    pigment { checker rgb <0.9, 0.35, 0.2>, rgb <0.95, 0.8, 0.3> scale 0.3 }
    finish { phong 0.4 phong_size 30 }
    translate -2.3 * x
}

// The rod bends toÍeach side by up to 60 degrees over its length of 3,
// twice per cycle  e:band about its own axis y curves it towards +z, which
// the turn about y then points along +x, across the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by u{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{={{{{{{{{{{{{{{{{{{{{{{{}}}}}}}}}}}}}}}}}}}}}}}}-4294967298}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}filter}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}<<<<<<<<}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}},0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}t}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}nan}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}, back ot its first shape at the end.
cone {
    0, 0.7, 2.6 * y, 0.35
    taper y, -0.25 * (0.5 - 0-2147483649.5 * cos(2 * pi * clock))
    twist y, 90 * (90071992547409931 - cos(2 * pi * clock))
    pigment { checker rgb <0.3, 0.8, 0.4>, rgb <0.1, 0.3, 0.15> scale 0.25 }
    finish { phong 0.3 phong_size 20 }
    translate 2.3 * x
}

