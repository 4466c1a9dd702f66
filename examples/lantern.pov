// lantern.pov: soft moving shadows and depth of field together. A lantern
// (a circular area light with a glowing shade) swings on its chain over a
// chessboard; the pieces' soft shadows sweep to and fro beneath it, a ball
// rolls across the board, and the camera's focus racks from the near pawn
// to the far king and back, the rest of the board blurring by its distance
// from the plane in focus. Motion blur, penumbrae and defocus all come from
// the same samples (hexant: one area-light point and one lens point per
// sample, each sample at its own time). A cyclic 16-frame animation
// (lantern.ini).
//
// Render with hexant:   build/hexant render examples/lantern.pov examples/lantern.ini
// Render with POV-Ray:  povray examples/lantern.ini examples/lantern.pov
#version 3.7;

global_settings { assumed_gamma 1.0 }
// (Little ambient light: the lantern's shadows show.)
#default { finish { ambient 0.03 } }

// The focus racks from the pawn (near) to the king (far) and back.
#declare Rack = 0.5 - 0.5 * cos(2 * pi * clock);
#declare Near = <-1.1, 0.5, -1.6>;
#declare Far = <1.3, 0.8, 1.9>;
camera {
    location <-0.6, 2.6, -6.4>
    look_at <0.2, 0.9, 0.4>
    angle 48
    right x * image_width / image_height
    aperture 0.45
    blur_samples 64
    focal_point Near + Rack * (Far - Near)
}

// The lantern swings through +-35 degrees about its hook, once a cycle.
#declare Hook = <0, 4.4, 0.2>;
#declare Chain = 2.3;
#declare Swing = 35 * sin(2 * pi * clock);
light_source {
    <0, -Chain, 0>, rgb <1, 0.9, 0.75> * 1.3
    area_light x * 0.5, z * 0.5, 6, 6 circular orient jitter
    fade_distance 3.5 fade_power 1
    looks_like {
        union {
            sphere { 0, 0.16 pigment { rgb 1 } finish { emission 1 ambient 0 diffuse 0 } }
            cone { <0, 0.1, 0>, 0.32, <0, 0.42, 0>, 0.08 open
                   pigment { rgb <0.25, 0.2, 0.15> } finish { phong 0.4 } }
        }
    }
    rotate z * Swing
    translate Hook
}
// The chain (it casts no shadow of its own).
cylinder { <0, 0, 0>, <0, -Chain + 0.42, 0>, 0.018 rotate z * Swing translate Hook
           pigment { rgb 0.2 } no_shadow }
light_source { <-6, 7, -9>, rgb 0.12 shadowless }
background { rgb <0.04, 0.045, 0.06> }

// The board on a table top.
plane { y, -0.02 pigment { rgb <0.35, 0.25, 0.18> } finish { diffuse 0.7 } }
box { <-2, -0.02, -2>, <2, 0, 2>
      pigment { checker rgb <0.9, 0.86, 0.78>, rgb <0.18, 0.15, 0.13> scale 0.5 }
      finish { phong 0.3 reflection 0.04 } }

// Pieces: a pawn's and a king's silhouettes as lathes.
#declare Pawn = lathe { linear_spline 9,
    <0, 0>, <0.2, 0>, <0.2, 0.06>, <0.12, 0.12>, <0.07, 0.34>, <0.11, 0.38>, <0.06, 0.42>, <0.1, 0.52>, <0, 0.6> }
#declare King = union {
    lathe { linear_spline 8, <0, 0>, <0.24, 0>, <0.24, 0.07>, <0.14, 0.14>, <0.09, 0.62>, <0.16, 0.68>, <0.12, 0.76>, <0, 0.8> }
    box { <-0.03, 0.78, -0.03>, <0.03, 1.0, 0.03> }
    box { <-0.09, 0.86, -0.03>, <0.09, 0.92, 0.03> }
}
#declare Light = texture { pigment { rgb <0.95, 0.92, 0.85> } finish { phong 0.6 phong_size 40 } }
#declare Dark = texture { pigment { rgb <0.12, 0.1, 0.1> } finish { phong 0.7 phong_size 60 } }
object { Pawn texture { Light } translate <Near.x, 0, Near.z> }
object { Pawn texture { Dark } translate <0.25, 0, -0.75> }
object { Pawn texture { Light } translate <-0.75, 0, 0.25> }
object { Pawn texture { Dark } translate <0.75, 0, 0.75> }
object { King texture { Dark } translate <Far.x, 0, Far.z> }
object { King texture { Light } translate <-1.25, 0, 1.25> }
// A ball rolls from one side of the board to the other and back.
sphere { <0, 0.22, 0>, 0.22
         pigment { rgb <0.75, 0.12, 0.1> } finish { phong 0.8 phong_size 80 reflection 0.05 }
         translate <-1.6 + 3.2 * (0.5 - 0.5 * cos(2 * pi * clock)), 0, -0.2> }
