// The atmosphere: media { } at the top, scattering (Rayleigh) and
// absorbing, inside a room of planes (hollow, so the camera's rays are in
// the open), a point light with media_attenuation and a cylinder light
// whose beam is a lit interval; clock moves the beam.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 1, 0> }
light_source { <3, 5, -3>, rgb 1.2 media_attenuation on }
light_source { <-2, 6, 0>, rgb <1, 0.8, 0.5> cylinder point_at <-2 + clock, 0, 0> radius 0.6 falloff 0.9 }
media {
  scattering { 4, rgb 0.04 }
  absorption 0.02
  intervals 2 samples 3
}
plane { y, 0 pigment { checker rgb 0.8, rgb 0.3 } hollow }
plane { z, 4 pigment { rgb <0.5, 0.6, 0.8> } hollow }
sphere { <1, 1, 0>, 0.8 pigment { rgb <0.2, 0.7, 0.3> } }
