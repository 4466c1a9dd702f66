// A scene of POV-Ray 3.6 dims each texture layer's own light by 3.6's
// opacity, 1 - (filter x the largest channel + transmit), where 3.7 takes
// 1 - filter - transmit (POV-Ray 3.7's trace.cpp keeps the old formula for
// legacy scenes): layered textures over partly clear pigments, one
// filtering, one transmitting, one both, turning with clock.
// (assumed_gamma is set: the legacy gamma rule is another test's.)
#version 3.6;
global_settings { assumed_gamma 1 }
camera { location <0, 1.5, -5> look_at <0, 0.5, 0> angle 45 }
light_source { <3, 6, -4> rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
plane { y, -0.5 pigment { checker rgb <1, 0.5, 0.3> rgb <0.3, 0.4, 0.9> } }
#declare Clear = texture { pigment { rgbf <0.98, 1, 0.98, 1> }
                           finish { specular 1 roughness 0.001 ambient 0 diffuse 0 } }
box { -0.5, 0.5 pigment { rgbf <0.9, 0.5, 0.2, 0.9> } texture { Clear }
      interior { ior 1.3 } rotate (20 + 60 * clock) * y translate <-1.3, 0.2, 0> }
sphere { 0, 0.6 pigment { rgbt <0.3, 0.9, 0.5, 0.5> } finish { ambient 0.2 diffuse 0.7 }
         texture { pigment { gradient y color_map { [0 rgbf <1, 1, 1, 1>] [0.5 rgbf <1, 0.2, 0.2, 0.6>] [1 rgbf 1] } scale 0.4 rotate 90 * clock * z } }
         translate <0, 0.3, 0.5> }
cylinder { <0, -0.48, 0>, <0, 0.8, 0>, 0.45
           texture { pigment { rgbft <0.2, 0.6, 1, 0.5, 0.3> } finish { ambient 0.3 diffuse 0.6 } }
           texture { pigment { rgbf <1, 1, 0.8, 0.8> } finish { diffuse 0.3 } }
           translate <1.3, 0, 0> }
