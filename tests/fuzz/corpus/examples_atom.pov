// atom.pov: after Figure 6 of Glassner's "Spacetime Ray Tracing for
// Animation" (IEEE CG&A, 1988). A nucleus and six electrons that spin at
// different speeds in tilted orbits around it, over a floor that catches
// their (blurred) shadows. A cyclic 64-frame animation: every orbit turns a
// whole number of times over the clock range 0..1, so the last frame leads
// back into the first.
//
// Render with hexant:   build/hexant render examples/atom.pov examples/atom.ini
// Check it:             build/hexant check examples/atom.pov examples/atom.ini
// Render with POV-Ray:  povray examples/atom.ini examples/atom.pov
#version 3.7;

global_settings { assumed_gamma 1.0 }

camera {
    location <0, 5, -11>
    look_at <0, 0.6, 0>
    angle 40
    right x * image_width / image_height   // square pixels at any size
}

light_source { <-6, 14, -8>, rgb 1 }
background { rgb <0.02, 0.02, 0.05> }

// The floor: a square polygon, checked so motion reads against it.
polygon {
    5, <-8, 0, -8>, <8, 0, -8>, <8, 0, 8>, <-8, 0, 8>, <-8, 0, -8>
    pigment { checker rgb <0.75, 0.75, 0.7>, rgb <0.45, 0.45, 0.5> scale 1.5 }
    finish { ambient 0.15 diffuse 0.8 }
}

#declare Nucleus_Height = 1.8;
sphere {
    <0, Nucleus_Height, 0>, 0.9
    pigment { rgb <0.9, 0.25, 0.15> }
    finish { phong 0.6 phong_size 40 }
}

// One electron: an orbit of radius R tilted by Tilt (degrees about x, then
// z), turning Turns times over the animation, starting at phase Phase; the
// tilted orbit itself precesses Precession times about the vertical. Whole
// numbers of turns keep the animation cyclic.
#macro Electron(R, Tilt, Turns, Precession, Phase, Colour)
    sphere {
        <R, 0, 0>, 0.22
        rotate y * (Phase + 360 * Turns * clock)
        rotate Tilt
        rotate y * 360 * Precession * clock
        translate y * Nucleus_Height
        pigment { Colour }
        finish { phong 0.8 phong_size 60 }
    }
#end

Electron(1.7, < 20, 0,  10>, 1,  0,   0, rgb <0.3, 0.5, 1.0>)
Electron(1.9, <-35, 0,  25>, 2,  1,  60, rgb <0.3, 1.0, 0.5>)
Electron(2.1, < 60, 0, -15>, 3, -1, 120, rgb <1.0, 0.9, 0.3>)
Electron(2.3, <-10, 0, -50>, 4,  0, 180, rgb <1.0, 0.4, 0.9>)
Electron(2.5, < 75, 0,  40>, 5,  1, 240, rgb <0.4, 1.0, 1.0>)
Electron(2.7, <-60, 0, -30>, 6, -1, 300, rgb <1.0, 0.6, 0.3>)

