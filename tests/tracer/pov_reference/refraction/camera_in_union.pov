// The eye inside several members of a glass union. POV-Ray splits a union
// into its members (Link_To_Frame), each with the union's one interior,
// and starts a camera ray with that interior once per member that holds
// the eye (InitRayContainerState): the ray passes straight through the
// inner surfaces and bends where it leaves the last. A clipped union stays
// whole: its interior is listed once. The members slide with clock.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 8 }
camera { location <0, 1, -1> look_at <0, 0.7, 3> angle 60 }
light_source { <4, 8, -6> rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.6, 0.7, 1>] [1 rgb <0.2, 0.3, 0.7>] } } }
plane { y, 0 pigment { checker rgb 1 rgb <0.2, 0.3, 0.8> scale 0.5 } }
union {
  sphere { <0, 1, 0>, 2.5 }
  sphere { <0.1 * clock, 1, -1>, 1 }
  sphere { <0, 1, -0.5 + 0.2 * clock>, 1 }
  pigment { rgbf <1, 1, 1, 1> } interior { ior 1.4 }
}
union {
  sphere { <1.2, 1.1, 2.5>, 0.5 }
  sphere { <1.5, 1.1, 2.5>, 0.5 }
  clipped_by { plane { y, 1.3 } }
  pigment { rgbf <0.9, 1, 0.9, 0.95> } interior { ior 1.3 }
}
sphere { <0.5, 0.5, 2>, 0.4 pigment { rgb <1, 0.2, 0.2> } }
box { <-1.5, 0.02, 3>, <-0.6, 0.9, 3.6> pigment { rgb <0.2, 0.8, 0.3> } }
