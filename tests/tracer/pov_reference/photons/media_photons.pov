// Media photons: a spotlight's beam through a glass ball inside a hollow
// box of scattering media; the photons the ball refracts are left in the
// media along their way, so the focused beam shows behind the ball.
// MediaSteps=0: no media photons; the media is still lit only through
// photons, as the box is a target that refracts the spotlight's photons.
#version 3.7;
#ifndef (MediaSteps) #declare MediaSteps = 60; #end
global_settings { assumed_gamma 1 max_trace_level 6
  photons { count 20000 media MediaSteps, 2 max_trace_level 6 } }
camera { location <0, 6, -3.5> look_at <0, 0.4, 0.3> angle 48 }
light_source { <0, 8, -4> rgb 0.3 photons { refraction off reflection off } media_interaction off }
light_source { <-9, 0.6, 0> rgb <1.3, 1.1, 0.9> spotlight radius 3 falloff 4 point_at <0, 0.6, 0>
  photons { refraction on reflection off } }
plane { y, 0 pigment { checker rgb 0.7 rgb 0.4 } finish { ambient 0 diffuse 0.7 } }
box { <-4, 0.01, -2>, <4, 1.5, 2> hollow
  pigment { rgbf 1 } finish { ambient 0 diffuse 0 }
  interior { media { scattering { 1, rgb 0.3 extinction 0 } method 3 intervals 1 samples 4 } }
  photons { target }
}
sphere { <-1.5, 0.6, 0>, 0.5
  pigment { rgbf 1 } finish { ambient 0 diffuse 0 specular 0.5 roughness 0.01 }
  interior { ior 1.5 }
  photons { target refraction on reflection off collect off }
}
