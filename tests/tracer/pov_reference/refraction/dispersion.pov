// Dispersion as POV-Ray 3.7 computes it (ComputeRefraction, trace.cpp;
// SpectralBand, spectral.h): a prism of strongly dispersive glass in
// front of thin white stripes, which it spreads into spectra; a ball of
// the default 7 bands beside one of 3, moving with clock; a ball with
// dispersion but no ior (POV-Ray then takes the atmosphere's index and no
// dispersion); water with its own dispersion inside a dispersive glass (a
// ray leaving the water into the glass takes the larger of the two band
// counts).
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 10 }
camera { location <0, 1.2, -6> look_at <0, 0.7, 0> angle 52 }
light_source { <3, 9, -6> rgb 1 }
// stripes: white lines on black, far behind
plane { -z, -4 pigment { gradient x color_map { [0 rgb 1] [0.08 rgb 1] [0.08 rgb 0.02] [1 rgb 0.02] } scale 0.6 }
        finish { ambient 1 diffuse 0 } }
plane { y, -1 pigment { checker rgb 0.8 rgb 0.3 scale 0.5 } }
#declare Clear = finish { ambient 0 diffuse 0 specular 0.6 roughness 0.005 }
// the prism: a triangle's extrusion
intersection {
  plane { -y, 0 }
  plane { <0.866, 0.5, 0>, 0.5 }
  plane { <-0.866, 0.5, 0>, 0.5 }
  plane { z, 0.5 } plane { -z, 0.5 }
  pigment { rgbf <1, 1, 1, 1> } finish { Clear }
  interior { ior 1.5 dispersion 1.25 }
  scale <1.4, 1.4, 1> translate <-1.6, 0.6, 0>
}
sphere { <0.2 + 0.3 * clock, 0.4, -0.5>, 0.55
  pigment { rgbf 1 } finish { Clear }
  interior { ior 1.6 dispersion 1.2 }
}
sphere { <1.5, 0.4, -0.5>, 0.55
  pigment { rgbf 1 } finish { Clear }
  interior { ior 1.6 dispersion 1.2 dispersion_samples 3 }
}
// dispersion without ior: none
sphere { <-0.6, -0.55, -1.6>, 0.4
  pigment { rgbf <1, 0.9, 0.9, 0.9> } finish { Clear }
  interior { dispersion 1.5 }
}
// water in a glass
union {
  difference {
    cylinder { <0, 0, 0>, <0, 1.2, 0>, 0.5 }
    cylinder { <0, 0.12, 0>, <0, 1.3, 0>, 0.42 }
    pigment { rgbf 1 } finish { Clear } interior { ior 1.5 dispersion 1.1 dispersion_samples 4 }
  }
  cylinder { <0, 0.14, 0>, <0, 0.9, 0>, 0.4
    pigment { rgbf 1 } finish { Clear } interior { ior 1.33 dispersion 1.3 dispersion_samples 6 } }
  translate <0.9, -0.99, -1.8>
}
