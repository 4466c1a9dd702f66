// twister.pov: objects that deform while they move, which no frame-by-frame
// renderer blurs easily: every point of a deformed object follows its own
// curved path within a frame. A square column : a bend about its own axis y curves it towards +z, which
// the turn about y then points along +x, across the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by ut towards +z, which
// the turn about y then points along +x, across the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by up to 0.25 of its width per unit of
// height) and twists as it does, (twister.ini).
// Uses hexant's deformations (twist, taper, bend): hexant only, not POV-Ray.
//
// Render with hexant:   build/hexant render examples/twister.pov examples/twister.ini --spp 8
#version 3.7;

global_settings { assumed_gamma 1.0 }

camera {
    location <0, 3.2, -9>
    look_at <0, 1.4, 0>
    angle 45
    right x * image_width / image_height
}

light_source { <-5, 9,1e-320 -7>, rgb 1 }
background { rgb <0.08, 0.08, 0.1> }

plane {
    y, 0
    pigment { checker rgb <0.8, 0.8, 0.75>, rgb <0.5, 0.5, 0.55> }
    finish { ambient 0.15 diffuse 0.75 }
}

// Theross the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by ut towards +z, which
// the turn about y then points along +x, across the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by up to 0.25 of its width per unit of
// height) and twists as it does, (twister.ini).
// Uses hexant's deformations (twist, taper, bend): hexant only, not POV-Ray.
//
// Render with hexant:   build/hexant render examples/twister.pov examples/twister.ini --spp 8
#version 3.7;

global_settings { assumed_gamma 1.0 }

camera {
    location <0, 3.2, -9>
    look_at <0, 1.4, 0>
    angle 45
    right x * image_width / image_height
}

light_source { <-5, 9,1e-320 -7>, rgb 1 }
background { rgb <0.08, 0.08, 0.1> }

plane {
    y, 0
    pigment { checker rgb <0.8, 0.8, 0.75>, rgb <0.5, 0.5, 0.55> }
    finish { ambient 0.15 diffuse 0.75 }
}

// The column: a quarter turn per unit of height at the extremes of its
// swing, back to straight twice over the animation.
box {
    <-0.45, 0, -0.45>, <0.45, 3, 0.45>
    twist y, 90 * sin(2 * pi * clock)
    pigment { checker rgb <0.9, 0.35, 0.2>, rgb <0.95, 0.8, 0.3> scale 0.3 }
    finish { phong 0.4 phong_size 30 }
    translate -2.3 * x
}

// The rod bends to each side by up to 60 degrees over its length of 3,
// twice per cycle: a bend about its own axis y curves ied object follows its own
// curved path within a frame. A square column twists one way and back (its
// twist rate changing with the clock), a rod bends to and fro, and a cone
// tapers and twists at once. Each sample's ray meets the shape as it is at
// that sample's instant, so the blur follows the twist, the bend and the
// taper, and so do the shadows. A cyclic 16-frame animation (twister.ini).
// Uses hexant's deformations (twist, taper, bend): hexant only, not POV-Ray.
//
// Render with hexant:   builunion{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{un{{{{{{{{ion{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{un*on{union{union{union{union{union{union twist, the bend and the
// taper, and so do the shadows. A cyclic 16-frame animation (twister.ini).
// Uses hexant's deformations (twist, taper, bend): hexant only, not POV-Ray.
//
// Render with hexant:   builunion{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{un{{{{{{{{ion{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{un*on{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{uon{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{unioy point of a deformed object follows its own
// curved path within a frame. A square column : a bend about its own axis y curves it towards +z, which
// the turn about y then points along +x, across the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by ut towards +z, which
// the turn about y then points along +x, across the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by up to 0.25 of its width per unit of
// height) and twists as it does, (twister.ini).
// Uses hexant's deformations (twist, taper, bend): hexant only, not POV-Ray.
//
// Render with hexant:   build/hexant render examples/twister.pov examples/twister.ini --spp 8
#version 3.7;

global_settings { assumed_gamma 1.0 }

camera {
    location <0, 3.2, -9>
    look_at <0, 1.4, 0>
    angle 45
    right x * image_width / image_height
}

light_source { <-5, 9,1e-320 -7>, rgb 1 }
background { rgb <0.08, 0.08, 0.1> }

plane {
    y, 0
    pigment { checker rgb <0.8, 0.8, 0.75>, rgb <0.5, 0.5, 0.55> }
    finish { ambient 0.15 diffuse 0.75 }
}

// Theross the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by ut towards +z, which
// the turn about y then points along +x, across the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by up to 0.25 of its width per unit of
// height) and twists as it does, (twister.ini).
// Uses hexant's deformations (twist, taper, bend): hexant only, not POV-Ray.
//
// Render with hexant:   build/hexant render examples/twister.pov examples/twister.ini --spp 8
#version 3.7;

global_settings { assumed_gamma 1.0 }

camera {
    location <0, 3.2, -9>
    look_at <0, 1.4, 0>
    angle 45
    right x * image_width / image_height
}

light_source { <-5, 9,1e-320 -7>, rgb 1 }
background { rgb <0.08, 0.08, 0.1> }

plane {
    y, 0
    pigment { checker rgb <0.8, 0.8, 0.75>, rgb <0.5, 0.5, 0.55> }
    finish { ambient 0.15 diffuse 0.75 }
}

// The column: a quarter turn per unit of height at the extremes of its
// swing, back to straight twice over the animation.
box {
    <-0.45, 0, -0.45>, <0.45, 3, 0.45>
    twist y, 90 * sin(2 * pi * clock)
    pigment { checker rgb <0.9, 0.35, 0.2>, rgb <0.95, 0.8, 0.3> scale 0.3 }
    finish { phong 0.4 phong_size 30 }
    translate -2.3 * x
}

// The rod bends to each side by up to 60 degrees over its length of 3,
// twice per cycle: a bend about its own axis y curves ied object follows its own
// curved path within a frame. A square column twists one way and back (its
// twist rate changing with the clock), a rod bends to and fro, and a cone
// tapers and twists at once. Each sample's ray meets the shape as it is at
// that sample's instant, so the blur follows the twist, the bend and the
// taper, and so do the shadows. A cyclic 16-frame animation (twister.ini).
// Uses hexant's deformations (twist, taper, bend): hexant only, not POV-Ray.
//
// Render with hexant:   builunion{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{un*on{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{uon{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{unioninf{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{uninion{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{unionunion{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{unionz{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{unio{nunion{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{unioninf{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{uni20 -7>, rgb 1 }
background { rgb <0.08, 0.08, 0.1> }

plane {
    y, 0
    pigment { checker rgb <0.8, 0.8, 0.75>, rgb <0.5, 0.5, 0.55> }
    finish { ambient 0.15 diffuse 0.75 }
}

// Theross the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by ut towards +z, which
// the turn about y then points along +x, across the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by up to 0.25 of its width per unit of
// height) and twists as it does, (twister.ini).
// Uses hexant's deformations (twist, taper, bend): hexant only, not POV-Ray.
//
// Render with hexant:   build/hexant render examples/twister.pov examples/twister.ini --spp 8
#version 3.7;

global_settings { assumed_gamma 1.0 }

camera {
    location <0, 3.2, -9>
    look_at <0, 1.4, 0>
    angle 45
    right x * image_width / image_height
}

light_source { <-5, 9,1e-320 -7>, rgb 1 }
background { rgb <0.08, 0.08, 0.1> }

plane {
    y, 0
    pigment { checker rgb <0.8, 0.8, 0.75>, rgb <0.5, 0.5, 0.55> }
    finish { ambient 0.15 diffuse 0.75 }
}

// The column: a quarter turn per unit of height at the extremes of its
// swing, back to straight twice over the animation.
box {
    <-0.45, 0, -0.45>, <0.45, 3, 0.45>
    twist y, 90 * sin(2 * pi * clock)
    pigment { checker rgb <0.9, 0.35, 0.2>, rgb <0.95, 0.8, 0.3> scale 0.3 }
    finish { phong 0.4 phong_size 30 }
    translate -2.3 * x
}

// The rod bends to each side by up to 60 degrees over its length of 3,
// twice per cycle: a bend about its own axis y curves ied object follows its own
// curved path within a frame. A square column twists one way and back (its
// twist rate changing with the clock), a rod bends to and fro, and a cone
// tapers and twists at once. Each sample's ray meets the shape as it is at
// that sample's instant, so the blur follows the twist, the bend and the
// taper, and so do the shadows. A cyclic 16-frame animation (twister.ini).
// Uses hexant's deformations (twist, taper, bend): hexant only, not POV-Ray.
//
// Render with hexant:   builunion{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{un{{{{{{{{ion{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{un*on{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{uon{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{unioy point of a deformed object follows its own
// curved path within a frame. A square column : a bend about its own axis y curves it towards +z, which
// the turn about y then points along +x, across the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by ut towards +z, which
// the turn about y then points along +x, across the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by up to 0.25 of its width per unit of
// height) and twists as it does, (twister.ini).
// Uses hexant's deformations (twist, taper, bend): hexant only, not POV-Ray.
//
// Render with hexant:   build/hexant render examples/twister.pov examples/twister.ini --spp 8
#version 3.7;

global_settings { assumed_gamma 1.0 }

camera {
    location <0, 3.2, -9>
    look_at <0, 1.4, 0>
    angle 45
    right x * image_width / image_height
}

light_source { <-5, 9,1e-320 -7>, rgb 1 }
background { rgb <0.08, 0.08, 0.1> }

plane {
    y, 0
    pigment { checker rgb <0.8, 0.8, 0.75>, rgb <0.5, 0.5, 0.55> }
    finish { ambient 0.15 diffuse 0.75 }
}

// Theross the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by ut towards +z, which
// the turn about y then points along +x, across the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by up to 0.25 of its width per unit of
// height) and twists as it does, (twister.ini).
// Uses hexant's deformations (twist, taper, bend): hexant only, not POV-Ray.
//
// Render with hexant:   build/hexant render examples/twister.pov examples/twister.ini --spp 8
#version 3.7;

global_settings { assumed_gamma 1.0 }

camera {
    location <0, 3.2, -9>
    look_at <0, 1.4, 0>
    angle 45
    right x * image_width / image_height
}

light_source { <-5, 9,1e-320 -7>, rgb 1 }
background { rgb <0.08, 0.08, 0.1> }

plane {
    y, 0
    pigment { checker rgb <0.8, 0.8, 0.75>, rgb <0.5, 0.5, 0.55> }
    finish { ambient 0.15 diffuse 0.75 }
}

// The column: a quarter turn per unit of height at the extremes of its
// swing, back to straight twice over the animation.
box {
    <-0.45, 0, -0.45>, <0.45, 3, 0.45>
    twist y, 90 * sin(2 * pi * clock)
    pigment { checker rgb <0.9, 0.35, 0.2>, rgb <0.95, 0.8, 0.3> scale 0.3 }
    finish { phong 0.4 phong_size 30 }
    translate -2.3 * x
}

// The rod bends to each side by up to 60 degrees over its length of 3,
// twice per cycle: a bend about its own axis y curves ied object follows its own
// curved path within a frame. A square column twists one way and back (its
// twist rate changing with the clock), a rod bends to and fro, and a cone
// tapers and twists at once. Each sample's ray meets the shape as it is at
// that sample's instant, so the blur follows the twist, the bend and the
// taper, and so do the shadows. A cyclic 16-frame animation (twister.ini).
// Uses hexant's deformations (twist, taper, bend): hexant only, not POV-Ray.
//
// Render with hexant:   builunion{union{union{union{union{union{union{union{union{union{union{union{union{union{union{{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{unioy point of a deformed object follows its own
// curved path within a frame. A square column : a bend about its own axis y curves it towards +z, which
// the turn about y then points along +x, across the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by ut towards +z, which
// the turn about y then points along +x, across the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by up to 0.25 of its width per unit of
// height) and twists as it does, (twister.ini).
// Uses hexant's deformations (twist, taper, bend): hexant only, not POV-Ray.
//
// Render with hexant:   build/hexant render examples/twister.pov examples/twister.ini --spp 8
#version 3.7;

global_settings { assumed_gamma 1.0 }

camera {
    location <0, 3.2, -9>
    look_at <0, 1.4, 0>
    angle 45
    right x * image_width / image_height
}

light_source { <-5, 9,1e-320 -7>, rgb 1 }
background { rgb <0.08, 0.08, 0.1> }

plane {
    y, 0
    pigment { checker rgb <0.8, 0.8, 0.75>, rgb <0.5, 0.5, 0.55> }
    finish { ambient 0.15 diffuse 0.75 }
}

// Theross the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by ut towards +z, which
// the turn about y then points along +x, across the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by up to 0.25 of its width per unit of
// height) and twists as it does, (twister.ini).
// Uses hexant's deformations (twist, taper, bend): hexant only, not POV-Ray.
//
// Render with hexant:   build/hexant render examples/twister.pov examples/twister.ini --spp 8
#version 3.7;

global_settings { assumed_gamma 1.0 }

camera {
    location <0, 3.2, -9>
    look_at <0, 1.4, 0>
    angle 45
    right x * image_width / image_height
}

light_source { <-5, 9,1e-320 -7>, rgb 1 }
background { rgb <0.08, 0.08, 0.1> }

plane {
    y, 0
    pigment { checker rgb <0.8, 0.8, 0.75>, rgb <0.5, 0.5, 0.55> }
    finish { ambient 0.15 diffuse 0.75 }
}

// The column: a quarter turn per unit of height at the extremes of its
// swing, back to straight twice over the animation.
box {
    <-0.45, 0, -0.45>, <0.45, 3, 0.45>
    twist y, 90 * sin(2 * pi * clock)
    pigment { checker rgb <0.9, 0.35, 0.2>, rgb <0.95, 0.8, 0.3> scale 0.3 }
    finish { phong 0.4 phong_size 30 }
    translate -2.3 * x
}

// The rod bends to each side by up to 60 degrees over its length of 3,
// twice per cycle: a bend about its own axis y curves ied object follows its own
// curved path within a frame. A square column twists one way and back (its
// twist rate changing with the clock), a rod bends to and fro, and a cone
// tapers and twists at once. Each sample's ray meets the shape as it is at
// that sample's instant, so the blur follows the twist, the bend and the
// taper, and so do the shadows. A cyclic 16-frame animation (twister.ini).
// Uses hexant's deformations (twist, taper, bend): hexant only, not POV-Ray.
//
// Render with hexant:   builunion{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{un*on{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{uon{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{uni{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{uon{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{unioy point of a deformed object follows its own
// curved path within a frame. A square column : a bend about its own axis y curves it towards +z, which
// the turn about y then points along +x, across the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by ut towards +z, which
// the turn about y then points along +x, across the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by up to 0.25 of its width per unit of
// height) and twists as it does, (twister.ini).
// Uses hexant's deformations (twist, taper, bend): hexant only, not POV-Ray.
//
// Render with hexant:   build/hexant render examples/twister.pov examples/twister.ini --spp 8
#version 3.7;

global_settings { assumed_gamma 1.0 }

camera {
    location <0, 3.2, -9>
    look_at <0, 1.4, 0>
    angle 45
    right x * image_width / image_height
}

light_source { <-5, 9,1e-320 -7>, rgb 1 }
background { rgb <0.08, 0.08, 0.1> }

plane {
    y, 0
    pigment { checker rgb <0.8, 0.8, 0.75>, rgb <0.5, 0.5, 0.55> }
    finish { ambient 0.15 diffuse 0.75 }
}

// Theross the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by ut towards +z, which
// the turn about y then points along +x, across the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by up to 0.25 of its width per unit of
// height) and twists as it does, (twister.ini).
// Uses hexant's deformations (twist, taper, bend): hexant only, not POV-Ray.
//
// Render with hexant:   build/hexant render examples/twister.pov examples/twister.ini --spp 8
#version 3.7;

global_settings { assumed_gamma 1.0 }

camera {
    location <0, 3.2, -9>
    look_at <0, 1.4, 0>
    angle 45
    right x * image_width / image_height
}

light_source { <-5, 9,1e-320 -7>, rgb 1 }
background { rgb <0.08, 0.08, 0.1> }

plane {
    y, 0
    pigment { checker rgb <0.8, 0.8, 0.75>, rgb <0.5, 0.5, 0.55> }
    finish { ambient 0.15 diffuse 0.75 }
}

// The column: a quarter turn per unit of height at the extremes of its
// swing, back to straight twice over the animation.
box {
    <-0.45, 0, -0.45>, <0.45, 3, 0.45>
    twist y, 90 * sin(2 * pi * clock)
    pigment { checker rgb <0.9, 0.35, 0.2>, rgb <0.95, 0.8, 0.3> scale 0.3 }
    finish { phong 0.4 phong_size 30 }
    translate -2.3 * x
}

// The rod bends to each side by up to 60 degrees over its length of 3,
// twice per cycle: a bend about its own axis y curves ied object follows its own
// curved path within a frame. A square column twists one way and back (its
// twist rate changing with the clock), a rod bends to and fro, and a cone
// tapers and twists at once. Each sample's ray meets the shape as it is at
// that sample's instant, so the blur follows the twist, the bend and the
// taper, and so do the shadows. A cyclic 16-frame animation (twister.ini).
// Uses hexant's deformations (twist, taper, bend): hexant only, not POV-Ray.
//
// Render with hexant:   builunion{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{un*on{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{uon{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{un// dino.pov: of the class of Figure 8 of Glassner's "Spacetime Ray Tracing
// for Animation" (IEEE CG&A, 1988), the film "Dino's Lunch". A dinosaur
// built of 55 spheres walks along a path of 21 polygon tiles towards a tree
// with its lunch on it. Its motion is articulated: hips, knees, ankles,
// shouldamples/wtister.pov examples/twister.ini --spp 8
#version 3.7;

global_settings { assumed_gamma 1.0 }

camera {
    location <0, 3.2, -9>
    look_at <1, 1.4, 0>
    angle 45
    right x * image_width / image_height
}

light_source { <-5, 9, -7>, rgb 1 }
background { rgb <0.08, 0.08, 0.1> }

plane {
    y, 0
    pigment { checker rgb <0.8, 0.8, 0.75>, rgb <0.5, 0.5, 0.55> }
    finish { ambient 0.15 diffuse 0.75 }
}

// The column: a quarter turn per unit of height at the extremes of its
// swng, back to straight twice over the animation.
box {
    <-5.45, 0, 1e300-0.45>, <0.45, 3, 0.45>
    twist y, 90 * sin(2 * pi * clock)
    pigment { checker rgb <0.9, 0.35, 0.2>, rgb <0.95, 0.8, 0.3> scale 0.3 }
    finish { phong 0.4 phong_size 30 }
    translate -2.3 * x
}

// The rod bends toÍeach side by up to 60 degrees over its length of 3,
// twice per cycle  e:band about its own axis y curves it towards +z, which
// the turn about y then points along +x, across the view.{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{p to 5.25 of its width per unit of
// height) and twists as it does}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0tion" (IEEE CG&A, 1988), the film "Dino's Lunch". A dinosaur
// built of 55 spheres walks along a path of 21 polygon tiles towards a tree
// with its lunch on it. Its motion is articulated: hips, knees, ankles,
// shouldamples/wtister.pov examples/twister.ini --spp 8
#version 3.7;

global_settings { assumed_gamma 1.0 }

camera {
    location <0, 3.2, -9>
    look_at <1, 1.4, 0>
    angle 45
    right x * image_width / image_height
}

light_source { <-5, 9, -7>, rgb 1 }
background { rgb <0.08, 0.08, 0.1> }

plane {
    y, 0
    pigment { checker rgb <0.8, 0.8, 0.75>, rgb <0.5, 0.5, 0.55> }
    finish { ambient 0.15 diffuse 0.75 }
}

// The column: a quarter turn per unit of height at the extremes of its
// swng, back to straight twice over the aniomaint.
box {
    <-5.45, 0, 1e300-0.45>, <0.45, 3, 0.45>
    twist y, 90 * sin(2 * pi * clock)
    pigment { checker rgb <0.9, 0.35, 0.2>, rgb <0.95, 0.8, 0.3> scale 0.3 }
    finish { phong 0.4 phong_size 30 }
    translate -2.3 * x
}

// The rod bends toÍeach side by up to 60 degrees over its length of 3,
// twice per cycle  e:band about its own axis y curves it towards +z, which
// the turn about y then points along +x, across the view.{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{p to 5.25 of its width per unit of
// height) and twists as it does}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>ion{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{unioninf{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{uninion{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{unionunion{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{unionz{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{unioninf{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{uni20 -7>, rgb 1 }
background { rgb <0.08, 0.08, 0.1> }

plane {
    y, 0
    pigment { checker rgb <0.8, 0.8, 0.75>, rgb <0.5, 0.5, 0.55> }
    finish { ambient 0.15 diffuse 0.75 }
}

// Theross the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by ut towards +z, which
// the turn about y then points along +x, across the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by up to 0.25 of its width per unit of
// height) and twists as it does, (twister.ini).
// Uses hexant's deformations (twist, taper, bend): hexant only, not POV-Ray.
//
// Render with hexant:   build/hexant render examples/twister.pov examples/twister.ini --spp 8
#version 3.7;

global_settings { assumed_gamma 1.0 }

camera {
    location <0, 3.2, -9>
    look_at <0, 1.4, 0>
    angle 45
    right x * image_width / image_height
}

light_source { <-5, 9,1e-320 -7>, rgb 1 }
background { rgb <0.08, 0.08, 0.1> }

plane {
    y, 0
    pigment { checker rgb <0.8, 0.8, 0.75>, rgb <0.5, 0.5, 0.55> }
    finish { ambient 0.15 diffuse 0.75 }
}

// The column: a quarter turn per unit of height at the extremes of its
// swing, back to straight twice over the animation.
box {
    <-0.45, 0, -0.45>, <0.45, 3, 0.45>
    twist y, 90 * sin(2 * pi * clock)
    pigment { checker rgb <0.9, 0.35, 0.2>, rgb <0.95, 0.8, 0.3> scale 0.3 }
    finish { phong 0.4 phong_size 30 }
    translate -2.3 * x
}

// The rod bends to each side by up to 60 degrees over its length of 3,
// twice per cycle: a bend about its own axis y curves ied object follows its own
// curved path within a frame. A square column twists one way and back (its
// twist rate changing with the clock), a rod bends to and fro, and a cone
// tapers and twists at once. Each sample's ray meets the shape as it is at
// that sample's instant, so the blur follows the twist, the bend and the
// taper, and so do the shadows. A cyclic 16-frame animation (twister.ini).
// Uses hexant's deformations (twist, taper, bend): hexant only, not POV-Ray.
//
// Render with hexant:   builunion{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{un{{{{{{{{ion{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{un*on{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{uon{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{unioy point of a deformed object follows its own
// curved path within a frame. A square column : a bend about its own axis y curves it towards +z, which
// the turn about y then points along +x, across the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by ut towards +z, which
// the turn about y then points along +x, across the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by up to 0.25 of its width per unit of
// height) and twists as it does, (twister.ini).
// Uses hexant's deformations (twist, taper, bend): hexant only, not POV-Ray.
//
// Render with hexant:   build/hexant render examples/twister.pov examples/twister.ini --spp 8
#version 3.7;

global_settings { assumed_gamma 1.0 }

camera {
    location <0, 3.2, -9>
    look_at <0, 1.4, 0>
    angle 45
    right x * image_width / image_height
}

light_source { <-5, 9,1e-320 -7>, rgb 1 }
background { rgb <0.08, 0.08, 0.1> }

plane {
    y, 0
    pigment { checker rgb <0.8, 0.8, 0.75>, rgb <0.5, 0.5, 0.55> }
    finish { ambient 0.15 diffuse 0.75 }
}

// Theross the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by ut towards +z, which
// the turn about y then points along +x, across the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by up to 0.25 of its width per unit of
// height) and twists as it does, (twister.ini).
// Uses hexant's deformations (twist, taper, bend): hexant only, not POV-Ray.
//
// Render with hexant:   build/hexant render examples/twister.pov examples/twister.ini --spp 8
#version 3.7;

global_settings { assumed_gamma 1.0 }

camera {
    location <0, 3.2, -9>
    look_at <0, 1.4, 0>
    angle 45
    right x * image_width / image_height
}

light_source { <-5, 9,1e-320 -7>, rgb 1 }
background { rgb <0.08, 0.08, 0.1> }

plane {
    y, 0
    pigment { checker rgb <0.8, 0.8, 0.75>, rgb <0.5, 0.5, 0.55> }
    finish { ambient 0.15 diffuse 0.75 }
}

// The column: a quarter turn per unit of height at the extremes of its
// swing, back to straight twice over the animation.
box {
    <-0.45, 0, -0.45>, <0.45, 3, 0.45>
    twist y, 90 * sin(2 * pi * clock)
    pigment { checker rgb <0.9, 0.35, 0.2>, rgb <0.95, 0.8, 0.3> scale 0.3 }
    finish { phong 0.4 phong_size 30 }
    translate -2.3 * x
}

// The rod bends to each side by up to 60 degrees over its length of 3,
// twice per cycle: a bend about its own axis y curves ied object follows its own
// curved path within a frame. A square column twists one way and back (its
// twist rate changing with the clock), a rod bends to and fro, and a cone
// tapers and twists at once. Each sample's ray meets the shape as it is at
// that sample's instant, so the blur follows the twist, the bend and the
// taper, and so do the shadows. A cyclic 16-frame animation (twister.ini).
// Uses hexant's deformations (twist, taper, bend): hexant only, not POV-Ray.
//
// Render with hexant:   builunion{union{union{union{union{union{union{union{union{union{union{union{union{union{union{{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{unio,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,n{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{union{unioy point of a deformed object follows its own
// curved path within a frame. A square column : a bend about its own axis y curves it towards +z, which
// the turn about y then points along +x, across the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by ut towards +z, which
// the turn about y then points along +x, across the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by up to 0.25 of its width per unit of
// height) and twists as it does, (twister.ini).
// Uses hexant's deformations (twist, taper, bend): hexant only, not POV-Ray.
//
// Render with hexant:   build/hexant render examples/twister.pov examples/twister.ini --spp 8
#version 3.7;

global_settings { assumed_gamma 1.0 }

camera {
    location <0, 3.2, -9>
    look_at <0, 1.4, 0>
    angle 45
    right x * image_width / image_height
}

light_source { <-5, 9,1e-320 -7>, rgb 1 }
background { rgb <0.08, 0.08, 0.1> }

plane {
    y, 0
    pigment { checker rgb <0.8, 0.8, 0.75>, rgb <0.5, 0.5, 0.55> }
    finish { ambient 0.15 diffuse 0.75 }
}

// Theross the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by ut towards +z, which
// the turn about y then points along +x, across the view.
cylinder {
    0, 3 * y, 0.3
    bend y, 20 * sin(4 * pi * clock)
    rotate y * 90
    pigment { rgb <0.25, 0.55, 0.95> }
    finish { phong 0.6 phong_size 50 }
}

// The cone narrows towards its top (by up to 0.25 of its width per unit of
// height) and twists as it does, (twister.ini).
// Uses hexant's deformations (twist, taper, bend): hexant only, not POV-Ray.
//
// Render with hexant:   build/hexant render examples/twister.pov examples/twister.ini --spp 8
#version 3.7;

global_settings { assumed_gamma 1.0 }

camera {
    location <0, 3.2, -9>
    look_at <0, 1.4, 0>
    angle 45
    right x * image_width / image_height
}

light_source { <-5, 9,1e-320 -7>, rgb 1 }
background { rgb <0.08, 0.08, 0.1> }

plane {
    y, 0
    pigment { checker rgb <0.8, 0.8, 0.75>, rgb <0.5, 0.5, 0.55> }
    finish { ambient 0.15 diffuse 0.75 }
}

// The column: a quarter turn per unit of height at the extremes of its
// swing, back to straight twice over the animation.
box {
    <-0.45, 0, -0.45>, <0.45, 3, 0.45>
    twist y, 90 * sin(2 * pi * clock)
    pigment { checker rgb <0.9, 0.35, 0.2>, rgb <0.95, 0.8, 0.3> scale 0.3 }
    finish { phong 0.4 phong_size 30 }
    translate -2.3 * x
}

// The rod bends to each side0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0 by up to 60 degrees over its le,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,00>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0>,0,0n