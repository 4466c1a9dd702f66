// clipped_by and bounded_by against POV-Ray 3.7 (tests/tracer/pov_reference_test.cpp).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.3, 0> angle 40 }
light_source { <-5, 10, -8>, rgb 1 }
background { rgb <0.2, 0.25, 0.3> }
// The ground: a half-space with a round pit, an intersection with an
// inverse member (unbounded: its surface is everywhere but the pit).
intersection {
    plane { y, -1 }
    sphere { <0.6, -1, 1.5>, 1.2 inverse }
    pigment { checker rgb 0.8, rgb 0.4 }
}
// A sphere cut by a plane that sinks with clock, then turned: the cut turns with it.
sphere { 0, 1
    clipped_by { plane { y, 0.3 - 0.6 * clock } }
    pigment { rgb <1, 0.3, 0.2> }
    translate <-2, 0, 0>
    rotate y * 20 * clock
}
// A box with a spherical hole: open where cut.
box { -0.8, 0.8
    rotate <0, 30, 0>
    clipped_by { sphere { 0, 1 inverse } }
    pigment { rgb <0.3, 0.8, 0.3> }
    translate <0.4, 0, 0.5>
}
// An infinite plane clipped by a box: a tile that moves with clock.
plane { z, 0
    clipped_by { box { <-0.6, -1, -1>, <0.6, 0.6, 1> } }
    pigment { rgb <0.3, 0.4, 1> }
    translate <2.2, 0, -0.5 + clock>
}
// A lens bounded by a box smaller than it: POV-Ray keeps a CSG object's
// bounds and tests it only for rays that meet them, which cuts it.
intersection {
    sphere { <-0.3, 0, 0>, 0.6 }
    sphere { <0.3, 0, 0>, 0.6 }
    bounded_by { box { <-1, -0.25 + 0.3 * clock, -1>, <1, 1, 1> } }
    pigment { rgb <0.9, 0.5, 1> }
    translate <2.4, 1.4, 1.5>
}
// clipped_by { bounded_by } on a union.
union {
    sphere { <-0.3, 0, 0>, 0.5 }
    sphere { <0.3, 0, 0>, 0.5 }
    bounded_by { box { <-1, -0.2, -1>, <1, 1, 1> } }
    clipped_by { bounded_by }
    pigment { rgb <1, 0.9, 0.2> }
    translate <-0.7, 1.3, 1.5>
}
// Two clips at once, the second written after a turn (it does not turn).
cylinder { <-0.5, 0, 0>, <0.5, 0, 0>, 0.35
    clipped_by { plane { y, 0.1 } }
    rotate z * 90
    clipped_by { plane { x, 0.1 } }
    pigment { rgb <0.2, 0.9, 0.9> }
    translate <1.2, 1.5, 2.5>
}
