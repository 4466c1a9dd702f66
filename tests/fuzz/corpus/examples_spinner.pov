// spinner.pov: spinning far faster than the frame rate. A three-bladed fan
// makes 40 turns in each frame and a striped top 25, so each blurs into a
// smooth disc, as a real camera sees them; a second fan beside them turns
// 15 degrees per frame, and its blades show as short smears. A
// frame-by-frame renderer that bounds each object over its frame sees the
// same discs but must intersect the fan at every sample's angle anyway;
// nothing about this scene is hard for spacetime rays, which meet each blade
// where it is at their own instant. A cyclic 8-frame animation
// (spinner.ini): over the clock every rotation comes back to where it began
// (the slow fan turns a third of a turn: its three blades look the same).
//
// Render with hexant:   build/hexant render examples/spinner.pov examples/spinner.ini --spp 16
// Render with POV-Ray:  povray examples/spinner.ini examples/spinner.pov
#version 3.7;

global_settings { assumed_gamma 1.0 }

camera {
    location <0, 2.3, -6.8>
    look_at <0, 1.3, 0>
    angle 52
    right x * image_width / image_height
}

light_source { <-4, 8, -7>, rgb 1 }
background { rgb <0.1, 0.1, 0.12> }

plane {
    y, 0
    pigment { checker rgb <0.75, 0.75, 0.7>, rgb <0.45, 0.45, 0.5> }
    finish { ambient 0.15 diffuse 0.75 }
}

#declare Frames = 8;   // as in spinner.ini: turns per frame times Frames is turns per clock

// A fan facing the camera: three blades on a hub, on a stand.
#macro Fan(Turns_Per_Frame, Colour)
    union {
        union {
            #for (I, 0, 2)
                box { <-0.2, 0.1, -0.02>, <0.2, 1.1, 0.02> rotate z * (120 * I) }
            #end
            sphere { 0, 0.18 }
            pigment { Colour }
            finish { phong 0.5 phong_size 40 }
            rotate z * 360 * Turns_Per_Frame * Frames * clock
            translate <0, 1.6, -0.1>
        }
        cylinder { 0, 1.6 * y, 0.06 pigment { rgb 0.3 } }
    }
#end

object { Fan(40, rgb <0.95, 0.3, 0.2>) translate -1.9 * x }
object { Fan(1 / 24, rgb <0.2, 0.5, 0.95>) translate 1.9 * x }

// A top with a checked skin, spinning 25 turns per frame about its own
// tilted axis: its checks average to an even colour.
union {
    cone { <0, 0.05, 0>, 0.0, <0, 0.75, 0>, 0.6 }
    sphere { <0, 0.75, 0>, 0.6 scale <1, 0.35, 1> translate 0.49 * y }
    cylinder { <0, 0.9, 0>, <0, 1.25, 0>, 0.06 }
    pigment { checker rgb <0.95, 0.85, 0.2>, rgb <0.15, 0.35, 0.2> scale 0.2 }
    finish { phong 0.4 phong_size 30 }
    rotate y * 360 * 25 * Frames * clock
    rotate z * 12
    translate <0, 0, -1.2>
}

