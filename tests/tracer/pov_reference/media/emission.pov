// Emitting media in hollow glass: a spherical density through a colour
// map and turbulence (interior/media/hollow2's kind), moving with clock,
// beside a box of constant emission, over a checker floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.8, 0> }
light_source { <5, 8, -6>, rgb 1 }
plane { y, 0 pigment { checker rgb <0.9, 0.9, 0.8>, rgb <0.3, 0.5, 0.3> } }
sphere { 0, 1
  pigment { rgbt <1, 1, 1, 1> }
  interior {
    media {
      emission 1.2
      intervals 1 samples 5 method 3
      density {
        spherical ramp_wave turbulence 0.2
        color_map { [0 rgb 0] [0.2 rgb <1, 0, 0>] [1 rgb <1, 1, 0>] }
      }
      translate <0.2 * clock, 0, 0>
    }
  }
  hollow
  translate <-1.2, 1, 0>
}
box { -0.8, 0.8
  pigment { rgbf <1, 1, 1, 1> }
  interior { media { emission <0.2, 0.4, 0.9> samples 2 } }
  hollow
  rotate y * (30 + 20 * clock)
  translate <1.3, 0.9, 0.5>
}
