// Seed: patterns, maps, normals, sky, fog and lights (issue 19).
#declare M = color_map { [0 rgb 1] [0.5, 1 color rgb <1, 0, 0> color rgb 0] }
sky_sphere { pigment { gradient y color_map { M } phase clock } emission 0.9 rotate x * 10 }
fog { fog_type 2 distance 5 fog_alt 0.5 fog_offset 0.2 color rgbt <1, 1, 1, 0.2> turbulence 0.3 }
camera { location <0, 1, -4> look_at 0 normal { ripples 0.1 frequency 3 } }
light_source { <2, 5, -3>, rgb 1 parallel point_at 0 }
plane { y, 0 pigment { brick rgb 1, rgb <0.5, 0.2, 0.1> brick_size <1, 0.3, 0.5> mortar 0.05 } }
sphere { 0, 1
  pigment { marble turbulence 0.5 octaves 3 omega 0.6 lambda 2.2 pigment_map { [0 checker scale 0.1] [1 rgb <0, 0, 1>] } }
  normal { bumps 0.4 scale 0.2 warp { turbulence 0.2 } no_bump_scale }
}
box { -1, 1 translate 3 * x pigment { wood sine_wave frequency 2 } normal { gradient x, 0.3 accuracy 0.01 } }
