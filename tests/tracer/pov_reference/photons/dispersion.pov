// Photons through a dispersive glass ball: each photon splits into the
// default 7 bands at the ball (POV-Ray 3.7's PhotonTrace), a caustic with
// coloured edges.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 6 photons { spacing 0.01 } }
camera { location <0, 3, -4> look_at <0, 0, 0.3> angle 45 }
light_source { <-3, 6, 2> rgb 1.2 photons { refraction on } }
plane { y, -1 pigment { rgb 0.8 } finish { diffuse 0.6 ambient 0 } }
sphere { <0, 0, 0>, 0.8
  pigment { rgbf 1 } finish { ambient 0 diffuse 0 specular 0.6 roughness 0.005 }
  interior { ior 1.5 dispersion 1.4 }
  photons { target refraction on reflection off }
}
