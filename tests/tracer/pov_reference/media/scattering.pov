// Scattering and absorbing media in a hollow box, lit by a spotlight (its
// cone cuts the ray into lit and unlit intervals) and a point light, one
// media Henyey-Greenstein, one isotropic with a density pattern; the
// box's shadow on the floor dimmed by the media's extinction.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 1, 0> }
light_source { <0, 6, 0>, rgb 2 spotlight point_at <0.5 * clock, 0, 0> radius 10 falloff 15 }
light_source { <-6, 5, -4>, rgb 0.6 }
plane { y, 0 pigment { checker rgb 0.8, rgb 0.4 } }
box { <-2, 0.01, -1.5>, <2, 3, 1.5>
  pigment { rgbt 1 }
  interior {
    media {
      scattering { 5, rgb 0.15 eccentricity 0.4 }
      absorption 0.05
      intervals 3 samples 3 method 3
    }
    media {
      scattering { 1, rgb <0.3, 0.2, 0.1> extinction 0.5 }
      density { bozo scale 0.7 color_map { [0 rgb 0] [1 rgb 1] } }
      method 3 samples 4 aa_level 2 aa_threshold 0.05
    }
  }
  hollow
}
sphere { <0.8, 0.7, 0>, 0.6 pigment { rgb <0.9, 0.3, 0.2> } }
