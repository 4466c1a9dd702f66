// glider.pov: an object that follows a spline path while the camera tracks
// it. A small glider flies a closed loop through keyframes (a cubic spline)
// among pillars, heading along its path and banking into the turns; the
// camera stands still but turns to keep the glider in the centre of the
// view. Within each frame the camera turns with the glider, so the glider
// stays sharp while the pillars and the floor blur: the motion blur of a
// panning camera, which needs every sample's camera and every sample's
// glider at the same instant. A cyclic 64-frame animation (glider.ini).
//
// Render with hexant:   build/hexant render examples/glider.pov examples/glider.ini --spp 8
// Render with POV-Ray:  povray examples/glider.ini examples/glider.pov
#version 3.7;

global_settings { assumed_gamma 1.0 }

// The loop, closed: the last keys repeat the first ones, so position and
// velocity at clock 1 equal those at clock 0.
#declare Path = spline {
    cubic_spline
    -0.125, <-3.0, 2.2, 3.0>,
    0,      <0.0, 1.6, 4.5>,
    0.125,  <3.5, 2.0, 3.5>,
    0.25,   <5.0, 2.6, 0.0>,
    0.375,  <3.0, 2.2, -3.5>,
    0.5,    <0.0, 1.4, -2.0>,
    0.625,  <-3.0, 1.8, -3.5>,
    0.75,   <-5.0, 2.4, 0.0>,
    0.875,  <-3.0, 2.2, 3.0>,
    1,      <0.0, 1.6, 4.5>,
    1.125,  <3.5, 2.0, 3.5>
}

// Where the glider is and which way it heads: the spline's value and a
// central difference of it (the heading angle about y, 0 along +x).
#declare Here = Path(clock);
#declare Ahead = Path(clock + 0.002);
#declare Behind = Path(clock - 0.002);
#declare Heading = degrees(atan2(Ahead.z - Behind.z, Ahead.x - Behind.x));
// Banking: the path's curvature, from the second difference (4 |d x dd| /
// |d|^3 with d the central and dd the second difference), tilts the wings
// into the turn as far as a glider at this speed would lean.
#declare Turn = (Ahead.x - 2 * Here.x + Behind.x) * (Ahead.z - Behind.z)
              - (Ahead.z - 2 * Here.z + Behind.z) * (Ahead.x - Behind.x);
#declare Span = vlength(<Ahead.x - Behind.x, 0, Ahead.z - Behind.z>);
#declare Bank = degrees(atan(12 * Turn / (Span * Span * Span)));

camera {
    location <0, 6, -11>
    look_at Here
    angle 32
    right x * image_width / image_height
}

light_source { <-6, 12, -9>, rgb 1 }
background { rgb <0.55, 0.7, 0.9> }

plane {
    y, 0
    pigment { checker rgb <0.85, 0.85, 0.8>, rgb <0.35, 0.45, 0.4> }
    finish { ambient 0.2 diffuse 0.7 }
}

// Pillars on a ring, inside and outside the loop.
#for (I, 0, 7)
    cylinder {
        0, 3.5 * y, 0.25
        translate x * (I < 4 ? 1.7 : 6.5)
        rotate y * (45 * I + 22.5)
        pigment { rgb <0.9, 0.55, 0.25> }
        finish { phong 0.4 phong_size 30 }
    }
#end

// The glider, nose along +x: a fuselage, a cone nose, wings and a tail fin.
union {
    sphere { 0, 0.5 scale <1.4, 0.35, 0.35> }
    cone { <0.6, 0, 0>, 0.25, <1.0, 0, 0>, 0.0 }
    box { <-0.25, -0.03, -1.3>, <0.25, 0.03, 1.3> }
    box { <-0.75, 0, -0.02>, <-0.5, 0.4, 0.02> }
    pigment { rgb <0.9, 0.15, 0.1> }
    finish { phong 0.8 phong_size 80 }
    scale 1.3
    rotate x * Bank
    rotate -y * Heading     // POV-Ray is left-handed: +x turns towards +z by -angle
    translate Here
}

