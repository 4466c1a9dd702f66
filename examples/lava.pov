// lava.pov: surfaces that are functions of clock. Three blobs of wax rise
// and sink in a lava lamp, merging and parting: one isosurface of a sum of
// Gaussian fields whose centres move with clock, so their motion blurs
// where they move fastest. Beside it a pond of ripples running outward a
// quarter wavelength a frame, a height field drawn as an isosurface whose
// function reads clock: each ripple blurs along its way out. Both
// are bounded in spacetime by interval arithmetic on their functions (no
// max_gradient needed). A cyclic 16-frame animation (lava.ini).
//
// Render with hexant:   build/hexant render examples/lava.pov examples/lava.ini --spp 8
// Render with POV-Ray:  povray examples/lava.ini examples/lava.pov
#version 3.7;

global_settings { assumed_gamma 1.0 }

camera {
    location <0, 2.3, -4.6>
    look_at <0, 0.85, 0.4>
    angle 50
    right x * image_width / image_height
}

light_source { <-4, 8, -6>, rgb 1 }
light_source { <5, 4, -5>, rgb 0.35 }
background { rgb <0.08, 0.08, 0.12> }

plane { y, 0 pigment { checker rgb <0.7, 0.7, 0.65>, rgb <0.4, 0.4, 0.45> } }

// The wax: three centres on vertical paths, each a full cycle of clock.
#declare Tau = 2 * pi;
#declare Field = function(px, py, pz, cx, cy, cz) {
    exp(-6 * ((px - cx) * (px - cx) + (py - cy) * (py - cy) + (pz - cz) * (pz - cz)))
}
#declare Wax = function {
    0.5 - Field(x, y, z, 0.1, 0.9 + 0.6 * sin(Tau * clock), 0)
        - Field(x, y, z, -0.15, 0.9 + 0.6 * sin(Tau * clock + 2.1), 0.1)
        - Field(x, y, z, 0.05, 0.9 + 0.6 * sin(Tau * clock + 4.2), -0.1)
}
isosurface {
    function { Wax(x, y, z) }
    contained_by { box { <-0.6, 0, -0.6>, <0.6, 1.9, 0.6> } }
    open
    pigment { rgb <1, 0.35, 0.1> }
    finish { ambient 0.25 diffuse 0.7 phong 0.6 phong_size 40 }
    translate <-1.1, 0.05, 0.9>
}
// The lamp's glass and its cap.
cylinder { <-1.1, 0, 0.9>, <-1.1, 2.05, 0.9>, 0.7 open
    pigment { rgbf <0.9, 0.95, 1, 0.92> } finish { phong 0.8 reflection 0.05 } }
cylinder { <-1.1, 2.05, 0.9>, <-1.1, 2.3, 0.9>, 0.72 pigment { rgb 0.25 } finish { phong 0.6 } }

// The pond: ripples running outward, a quarter wavelength in each frame.
isosurface {
    function { y - 0.06 * sin(18 * sqrt(x * x + z * z) - Tau * 4 * clock) }
    contained_by { box { <-1.2, -0.1, -1.2>, <1.2, 0.1, 1.2> } }
    pigment { rgb <0.25, 0.5, 0.8> }
    finish { diffuse 0.6 phong 0.9 phong_size 60 }
    translate <1.1, 0.12, 0.2>
}
