// caustics.pov: light as POV-Ray renders it, in time. A glass ball rolls to
// and fro across a sunlit room; its caustic, the bright spot its glass
// focuses on the floor, runs beside it (photons), the walls light each
// other and the ball (radiosity: the red wall tints the floor), and a
// ground fog lies over the floor. Each photon is shot at a time of its own
// across the frame's shutter, so the caustic blurs as the ball does. A
// cyclic 16-frame animation (caustics.ini).
//
// Render with hexant:   build/hexant render examples/caustics.pov examples/caustics.ini
// Render with POV-Ray:  povray examples/caustics.ini examples/caustics.pov
#version 3.7;

global_settings {
    assumed_gamma 1.0
    max_trace_level 8
    radiosity {
        pretrace_start 0.08
        pretrace_end 0.02
        count 60
        nearest_count 5
        error_bound 1.0
        recursion_limit 1
    }
    photons { spacing 0.01 autostop 0 }
}

camera {
    location <0.4, 2.6, -5.2>
    look_at <0, 0.5, 0.4>
    angle 52
    right x * image_width / image_height
}

// The sun, low through the open side of the room.
light_source { <-7, 3.6, -0.5> color rgb <1.4, 1.3, 1.1> }

#declare Wall = finish { diffuse 0.75 ambient 0 }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.6 scale 0.7 } finish { Wall } }
plane { -z, -2.6 pigment { rgb 0.85 } finish { Wall } }
plane { -x, -2.8 pigment { rgb <0.8, 0.15, 0.1> } finish { Wall } }
plane { -y, -4 pigment { rgb 0.9 } finish { Wall } }
// Behind the camera: a wall, so that radiosity's rays meet something.
plane { z, -7 pigment { rgb 0.5 } finish { Wall } }

// A white column and a blue box that stand still.
cylinder { <1.7, 0, 1.5>, <1.7, 2.2, 1.5>, 0.3 pigment { rgb 0.9 } finish { Wall } }
box { <-2.1, 0, 1.2>, <-1.3, 0.6, 2.0> rotate 20 * y pigment { rgb <0.2, 0.35, 0.8> } finish { Wall } }

// The glass ball rolls from left to right and back (cyclic).
#declare Roll = 0.5 - 0.5 * cos(2 * pi * clock);
#declare R = 0.55;
#declare X = -1.3 + 2.4 * Roll;
sphere {
    0, R
    rotate -z * degrees(X / R)
    translate <X, R, 0.2>
    pigment { rgbf <0.97, 0.98, 1, 0.96> }
    finish { ambient 0 diffuse 0 specular 0.7 roughness 0.003 reflection 0.06 }
    interior { ior 1.5 }
    photons { target refraction on reflection on }
}

// Ground fog: thick at the floor, thinning above it.
fog { fog_type 2 distance 14 color rgb <0.85, 0.88, 0.95> fog_offset 0 fog_alt 0.35 }
