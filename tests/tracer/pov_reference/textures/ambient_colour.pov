// ambient and emission as colours (POV-Ray 3.7's Parse_Finish reads both
// as colours; a float is grey), one of them moving with clock; a layered
// texture's colour ambient seen through the layer above.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb <1, 0.9, 0.8> }
camera { location <0, 1.5, -6> look_at <0, 0.3, 0> angle 50 }
light_source { <-4, 6, -5> rgb 0.8 }
background { rgb 0.05 }
plane { y, -1 pigment { checker rgb 0.6, rgb 0.3 } finish { ambient rgb <0.05, 0.1, 0.3> } }
sphere { <-1.6, 0, 0>, 0.8 pigment { rgb <0.9, 0.8, 0.7> }
  finish { ambient rgb <0.6, 0.2 + 0.4 * clock, 0.1> diffuse 0.4 } }
sphere { <0, 0, 0.5>, 0.8 pigment { rgb 0.8 }
  finish { ambient 0 emission rgb <0, 0.3, 0.5 * (1 - clock)> diffuse 0.5 phong 0.5 } }
sphere { <1.6, 0, 0>, 0.8
  texture { pigment { rgb <0.2, 0.9, 0.3> } finish { ambient rgb <0.7, 0.1, 0.5> } }
  texture { pigment { gradient y color_map { [0 rgbf <1, 1, 1, 1>] [1 rgbf <0.3, 0.3, 1, 0.2>] } }
            finish { ambient rgb <0.1, 0.4, 0.1> emission 0.1 } } }
