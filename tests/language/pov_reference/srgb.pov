// Reference scene for hexant's interpreter tests: every #debug line is
// NAME = VALUE, floats printed with str(v, 0, 10). See README.md.
#version 3.7;
// sRGB colours (need assumed_gamma).

global_settings { assumed_gamma 1.0 }  // POV-Ray parses srgb only after this
#declare R = srgb <0.5, 0.25, 1>;
#debug concat("srgb.red = ", str(R.red, 0, 10), "\n")
#debug concat("srgb.green = ", str(R.green, 0, 10), "\n")
#debug concat("srgb.blue = ", str(R.blue, 0, 10), "\n")
#debug concat("srgb.filter = ", str(R.filter, 0, 10), "\n")
#debug concat("srgb.transmit = ", str(R.transmit, 0, 10), "\n")
#declare R = srgbf <0.5, 0.25, 1, 0.3>;
#debug concat("srgbf.red = ", str(R.red, 0, 10), "\n")
#debug concat("srgbf.green = ", str(R.green, 0, 10), "\n")
#debug concat("srgbf.blue = ", str(R.blue, 0, 10), "\n")
#debug concat("srgbf.filter = ", str(R.filter, 0, 10), "\n")
#debug concat("srgbf.transmit = ", str(R.transmit, 0, 10), "\n")
#declare R = srgbt <0.04, 0.8, 0, 0.6>;
#debug concat("srgbt.red = ", str(R.red, 0, 10), "\n")
#debug concat("srgbt.green = ", str(R.green, 0, 10), "\n")
#debug concat("srgbt.blue = ", str(R.blue, 0, 10), "\n")
#debug concat("srgbt.filter = ", str(R.filter, 0, 10), "\n")
#debug concat("srgbt.transmit = ", str(R.transmit, 0, 10), "\n")
#declare R = srgbft <0.2, 0.3, 0.4, 0.5, 0.6>;
#debug concat("srgbft.red = ", str(R.red, 0, 10), "\n")
#debug concat("srgbft.green = ", str(R.green, 0, 10), "\n")
#debug concat("srgbft.blue = ", str(R.blue, 0, 10), "\n")
#debug concat("srgbft.filter = ", str(R.filter, 0, 10), "\n")
#debug concat("srgbft.transmit = ", str(R.transmit, 0, 10), "\n")
#declare R = srgb 0.5;
#debug concat("srgb_float.red = ", str(R.red, 0, 10), "\n")
#debug concat("srgb_float.green = ", str(R.green, 0, 10), "\n")
#debug concat("srgb_float.blue = ", str(R.blue, 0, 10), "\n")
#debug concat("srgb_float.filter = ", str(R.filter, 0, 10), "\n")
#debug concat("srgb_float.transmit = ", str(R.transmit, 0, 10), "\n")
