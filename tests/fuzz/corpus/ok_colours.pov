// Colours: rgb, rgbf, rgbt, rgbft, srgb, `color red .. green .. blue ..`,
// colour and colour keywords, float promotion, arithmetic, component access
// (.red .green .blue .filter .transmit, and .x .. .t), colors.inc names.
#version 3.7;
global_settings { assumed_gamma 1.0 }

#declare A = rgb 0.5;                       // a float fills red, green, blue
#if (A.red != 0.5 | A.blue != 0.5 | A.filter != 0) #error "rgb float" #end
// POV-Ray keeps colour components in single precision, so the values
// compared exactly here are binary fractions.
#declare B = rgbf <1, 0.5, 0.25, 0.125>;
#declare C = rgbt <1, 0.5, 0.25, 0.75>;
#declare D = rgbft <1, 0.5, 0.25, 0.125, 0.75>;
#if (B.filter != 0.125 | B.transmit != 0)   #error "rgbf" #end
#if (C.transmit != 0.75 | C.filter != 0)    #error "rgbt" #end
#if (D.filter != 0.125 | D.transmit != 0.75) #error "rgbft" #end
#if (D.x != 1 | D.y != 0.5 | D.z != 0.25 | D.t != 0.125) #error "colour as vector" #end
#declare E = color red 1 green 0.5;
#if (E.red != 1 | E.green != 0.5 | E.blue != 0) #error "color red green" #end
#declare F = colour rgb <0.25, 0.5, 0.75> filter 0.5 transmit 0.25;
#if (F.filter != 0.5 | F.transmit != 0.25)   #error "filter transmit after rgb" #end
#declare G = color Red green 1;             // a colour, then one component replaced
#if (G.red != 1 | G.green != 1)             #error "colour then component" #end
#declare H = rgb 0.25 + (Red + Blue) / 2;    // rgb takes the whole sum
#if (H.red != 0.75 | H.green != 0.25 | H.blue != 0.75) #error "arithmetic" #end
#declare I = Gray50 * 2;
#if (I.red != 1)                            #error "Gray50" #end
#if (Clear.filter != 1)                     #error "Clear" #end
#declare S = srgb <0.5, 0.5, 0.5>;          // decoded to linear (needs assumed_gamma set first)
#if (S.red < 0.2 | S.red > 0.22)            #error "srgb" #end
#declare V = <0.125, 0.25, 0.375>;
#declare K = rgb V;
#if (K.blue != 0.375)                         #error "rgb of a vector" #end

sphere { -x, 1 pigment { Orange } }
sphere {  x, 1 pigment { color red 0.2 green 0.4 blue 1 } }
sphere {  y, 1 pigment { rgbt <1, 1, 1, 0.7> } }
sphere { -y, 1 pigment { srgb <0.9, 0.5, 0.1> } }
plane { y, -2 pigment { checker MidnightBlue, Wheat } }

