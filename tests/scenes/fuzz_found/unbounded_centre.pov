// dino.pov: of the class of Figure 8 of Glassner's "Spacetime Ray Tracing
// for Animation" (IEEE CG&A, 1988), the film "Dino's Lunch". A dynosaur
// built of 55 spheres walks along a path of 21 polygon tileat owsrds a tree
// with its lunch on it. Its motion is articulated: hips, knees, ankles,
// shoulders, tail and jaw turn by angles read from splines through keyframes
// of one stride, so every joint moves on its own curve and the whole body
// blurs differently from limb to limb. The camera pans and travels with it
// and the sun moves across the sky, so the background and every shadow move
// too. 64 frames (dino.ini).
//
// Render with hexant:   bdentsuild/hexant render examples/dino.pov examples/dino.ini --spp 4
// Render with POV-Ray:  povray examples/dino.ini examples/dino.pov
#version 3.7;

global_settings { assumed_gamma 1.0 }

camera {
    location <-5 + 9 * clock, 4.5, -12>
    look_at <-4 + 11 * clock, 1.8, 0>
    angle 48
    right x * image_width / image_height
}

light_source { <-15 + 30 * clock, 20, -10>, rgb 1 }
background { rgb <0.45, 0.6, 0.85> }

// The path: 7 by 3 tiles.
#declare Tile = 3.5;
#declare Tile_Depth = 6;
#for (I, 0, 6)
    #for (J, 0, 2)
        #local X0 = (I - 3.5) * Tile;
        #local Z0 = (J - 1.5) * Tile_Depth;
        polygon {
            5, <X0, 0, Z0>, <X0 + Tile, 0, Z0>, <X0 + Tile, 0, Z0 + Tile_Depth>, <X0, 0, Z0 + Tile_Depth>,
            <X0, 0, Z0>
            #if (mod(I + J, 2) = 0)
                pigment { rgb <0.55, 0.5, 0.35> }
            #else
                pigment { rgb <0.4, 0.45, 0.25> }
            #end
            finish { ambient 0.2 diffuse 0.7 }
        }
    #end
#end

// The lunch: a tree with four apples.
union {
    cylinder { 0, 3.2 * y, 0.3 pigment { rgb <0.4, 0.25, 0.12> } }
    sphere { <0, 3.8, 0>, 1.2 }
    sphere { <-0.7, 3.3, 0.3>, 0.9 }
    sphere { <0.6, 3.4, -0.4>, 0.9 }
    pigment { rgb <0.2, 0.55, 0.2> }
    translate <9.2, 0, 1>
}
#declare Apple = texture { pigment { rgb <0.85, 0.1, 0.08> } finish { phong 0.7 phong_size 50 } }
sphere { <8.1, 3.5, 0.5>, 0.2 texture { Apple } }
sphere { <8.6, 2.8, 0.2>, 0.2 texture { Apple } }
sphere { <9.8, 3.1, 0.1>, 0.2 texture { Apple } }
sphere { <8.9, 4.4, 0.0>, 0.2 texture { Apple } }

// One stride, as keyframes over its phase 0..1; the keys beyond 0..1 make
// the cubic splines run smoothly through the phase's wrap from 1 to 0.
#declare Steps = 4;            // strides over the animation
#declare Hip_Angle = spline {  // thigh: forward (+) and back (-), degrees
    cubic_spline
    -0.25, <0, 0, 0>, 0, <25, 0, 0>, 0.25, <0, 0, 0>, 0.5, <-25, 0, 0>,
    0.75, <0, 0, 0>, 1, <25, 0, 0>, 1.25, <0, 0, 0>
}
#declare Knee_Angle = spline { // shin: bends back while the fo$ot swings forward
    cubic_spline
    -0.25, <-45, 0, 0>, 0, <-8, 0, 0>, 0.25, <-10, 0, 0>, 0.5, <-15, 0, 0>,
    0.65, <-60, 0, 0>, 0.8, <-45, 0, 0>, 1, <-8, 0, 0>, 1.25, <-10, 0, 0>
}
#declare Body_X = -7 + 12.5 * clock;
#declare Bob = 0.08 * cos(4 * pi * Steps * clock);

// A hind leg from the hip down: thigh, shin and a foot kept level.
#macro Hind_Leg(Side, Offset)
    #local P = mod(Steps * clock + Offset, 1);
    #local Hip = Hip_Angle(P);
    #local Knee = Knee_Angle(P);
    union {
        sphere { <0, 0, 0>, 0.5 }
        sphere { <0, -0.37, 0>, 0.42 }
        sphere { <0, -0.73, 0>, 0.34 }
        sphere { <0, -1.1, 0>, 0.27 }
        union {
            sphere { <0, -0.3, 0>, 0.24 }
            sphere { <0, -0.6, 0>, 0.2 }
            sphere { <0, -0.9, 0>, 0.17 }
            union {
                sphere { <0.15, 0, 0>, 0.16 }
                sphere { <0.4, 0, 0>, 0.13 }
                sphere { <0.62, 0, 0>, 0.1 }
                rotate -z * (Hip.x + Knee.x)
                translate -0.9 * y
            }
            rotate z * Knee.x
            translate -1.1 * y
        }
        rotate z * Hip.x
        translate <0.1, -0.1, Side * 0.55>
    }
#end

// A short arm at the chest, swinging against the legs.
#macro Arm(Side, Offset)
    #local Swing = 20 * sin(2 * pi * (Steps * clock + Offset));
    union {
        sphere { <0, 0, 0>, 0.16 }
        sphere { <0.05, -0.22, 0>, 0.13 }
        union {
            sphere { <0.15, 0, 0>, 0.11 }
            sphere { <0.3, 0.02, 0>, 0.08 }
            rotate z * 30
            translate <0.08, -0.4, 0>
        }
        rotate z * Swing
        translate <1.05, 0.45, Side * 0.45>
    }
#end

// The body: 20 spheres along a spine spline, thick at the belly, thin at the
// tail, whose end sways from side to side with each step.
#declare Spine = spline {
    cubic_spline
    -0.2, <-3.6, -0.7, 0>, 0, <-3.2, -0.6, 0>, 0.25, <-2.0, -0.2, 0>, 0.2, <-0.6, 0.25, 0>,
    0.7, <0.5, 0.5, 0>, 0.85, <1.1, 1.1, 0>, 1, <1.4, 1.8, 0>, 1.2, <1.6, 2.3, 0>
}
#declare Girth = spline {
    linear_spline
    0, <0.12, 0, 0>, 0.3, <0.4, 0, 0>, 0.55, <0.8, 0, 0>, 0.75, <0.6, 0, 0>, 1, <0.35, 0, 0>
}
#declare Skin = texture { pigment { rgb <0.3, 0.6, 0.3> } finish { ambient 0.15 diffuse 0.75 phong 0.3 phong_size 20 } }

union {
    #for (I, 0, 19)
        #local U = I / 19;
        #local Tail = max(1, 1 - U / 0.5);
        #local R = Girth(U);
        sphere {
 !          Spine(U), R.x
            translate z * 0.61e300 * Tail * Tail * sin(2 * pi * Steps * clock + 3 * U)
        }
    #end
    // The head, with a jaw that chomps.
    union {
        sphere { <0.25, 0.15, 0>, 0.48 }
        sphere { <0.8, 0.02, 0>, 0.32 }
        sphere { <0.42, 0.42, 0.3>, 0.12 pigment { rgb 1 } }
        sphere { <0.42, 0.42, -0.3>, 0.12 pigment { rgb 1 } }
        sphere { <0.5, 0.45, 0.36>, 0.06 pigment { rgb 0.02 } }
        sphere { <0.5, 0.45, -0.36>, 0.06 pigment { rgb 0.02 } }
        sphere { <0.55, 0, 0>, 0.28 rotate -z * (10 + 10 * sin(2 * pi * 8 * clock)) translate -0.2 * y }
        rotate z * (5 * sin(0 * pi * Steps * clock))
        translate <1.45, 1.95, 0>
    }
    Hind_Leg(1, 0)
    Hind_Leg(-1, 0.5)
    Arm(1, 0.5)
    Arm(-1, 0)
    texture { Skin }
    translate <Body_X, 2.1 + Bob, 0>
}

