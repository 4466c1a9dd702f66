// Media in a union's own interior { }: POV-Ray splits the union into its
// members, which share the union's interior and so its media. A hollow
// glass union of two spheres and a box, apart, with absorbing and
// emitting media, turning with clock, and a second union with media of
// its own. (Members that overlap are left out: there POV-Ray's list of
// interiors counts the overlap as outside the union, a rule hexant's
// media do not follow yet.)
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -5> look_at <0, 1, 0> angle 45 }
light_source { <3, 6, -4> rgb 1 }
background { rgb <0.3, 0.35, 0.5> }
plane { y, -0.02 pigment { checker rgb 0.9 rgb 0.4 } }
union {
  sphere { <-1, 1, 0>, 0.7 }
  box { <-0.2, 0.7, -0.3>, <0.3, 1.3, 0.3> }
  sphere { <1, 1, 0>, 0.5 }
  hollow
  pigment { rgbf <1, 1, 1, 0.95> } finish { reflection { 0, 1 fresnel } }
  interior { ior 1.5 media { absorption <1, 0.4, 0.1> emission <0.05, 0.1, 0.2> } }
  rotate 40 * clock * y
}
union {
  sphere { <-0.3, 0.4, -1>, 0.25 }
  sphere { <0.3, 0.4, -1>, 0.25 }
  hollow
  pigment { rgbt 1 }
  interior { media { emission <0.6, 0.3, 0.1> } }
}
