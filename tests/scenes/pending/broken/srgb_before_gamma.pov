// error: 3:14: assumed_gamma
// povray: line 3: Parse Error: Cannot parse sRGB colors before assumed_gamma has been set.
#declare C = srgb <0.5, 0.5, 0.5>;
global_settings { assumed_gamma 1.0 }
