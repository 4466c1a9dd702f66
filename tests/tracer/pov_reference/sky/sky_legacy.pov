// sky.pov under #version 3.6: POV-Ray 3.7 layers a legacy scene's
// sky_sphere as 3.6 did (the filters and transmits of the layers
// multiplied together). tests/tracer/pov_reference_test.cpp compares
// hexant's stills with POV-Ray 3.7's (README.md, "Sky").
#version 3.6;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0.5, -4> look_at <0, 1, 0> angle 90 }
background { rgb <0.3, 0.1, 0> }
sky_sphere {
  pigment { gradient y color_map { [0 rgbt <0.9, 0.9, 1, 0.3>] [0.7 rgb <0.1, 0.2, 0.8>] [1 rgb <0, 0, 0.3>] }
            phase 0.2 * clock }
  pigment { bozo turbulence 0.4 scale 0.2
            color_map { [0.4 rgbt 1] [0.6 rgbf <1, 0.9, 0.8, 0.5>] [0.8 rgb <1, 1, 1>] } }
  emission <1, 0.95, 0.9>
  rotate z * (10 + 20 * clock)
}
sphere { <0, 1, 0>, 0.7 pigment { rgb <1, 0.5, 0> } finish { ambient 1 diffuse 0 } }
