// bounce.pov: after Figure 7 of Glassner's "Spacetime Ray Tracing for
// Animation" (IEEE CG&A, 1988). Eight spheres bounce on the eight faces of
// an octagonal prism that lies in a small open box. Each bounce is a real
// contact: a sphere's height above its face is |sin|, so its velocity flips
// at the instant it touches, and every contact falls in the middle of a
// frame's shutter: the blur of a bouncing sphere is a "V" that ends on the
// face, not a streak through it. A cyclic 16-frame animation (bounce.ini):
// every sphere bounces a whole number of times over the clock range 0..1.
//
// Render with hexant:   build/hexant render examples/bounce.pov examples/bounce.ini --spp 4
// Render with POV-Ray:  povray examples/bounce.ini examples/bounce.pov
#version 3.7;

global_settings { assumed_gamma 1.0 }

camera {
    location <0.8, 1.2, -8.2>
    look_at <0, 0, 0>
    angle 54
    right x * image_width / image_height
}

light_source { <-3, 5, -8>, rgb 1 }
light_source { <4, -1, -6>, rgb 0.25 shadowless }
background { rgb <0.05, 0.05, 0.08> }

// The small box around it all, open towards the camera: back wall, floor,
// ceiling and the two side walls.
#declare Wall = 3.2;
#declare Back = 3.0;
#declare Wall_Texture = texture {
    pigment { checker rgb <0.8, 0.78, 0.7>, rgb <0.55, 0.55, 0.6> scale 0.8 }
    finish { ambient 0.12 diffuse 0.8 }
}
polygon { 5, <-Wall, -Wall, Back>, <Wall, -Wall, Back>, <Wall, Wall, Back>, <-Wall, Wall, Back>, <-Wall, -Wall, Back>
          texture { Wall_Texture } }
polygon { 5, <-Wall, -Wall, -Back>, <Wall, -Wall, -Back>, <Wall, -Wall, Back>, <-Wall, -Wall, Back>, <-Wall, -Wall, -Back>
          texture { Wall_Texture } }
polygon { 5, <-Wall, Wall, -Back>, <Wall, Wall, -Back>, <Wall, Wall, Back>, <-Wall, Wall, Back>, <-Wall, Wall, -Back>
          texture { Wall_Texture } }
polygon { 5, <-Wall, -Wall, -Back>, <-Wall, Wall, -Back>, <-Wall, Wall, Back>, <-Wall, -Wall, Back>, <-Wall, -Wall, -Back>
          texture { Wall_Texture } }
polygon { 5, <Wall, -Wall, -Back>, <Wall, Wall, -Back>, <Wall, Wall, Back>, <Wall, -Wall, Back>, <Wall, -Wall, -Back>
          texture { Wall_Texture } }

// The octagonal prism and its spheres are built with the prism's axis along
// z, its faces' normals at 0, 45, ..., 315 degrees about z, each face
// Apothem from the axis; then all of it turns so that the axis runs across
// the view.
union {
    #declare Apothem = 0.9;
    #declare Half_Face = Apothem * tan(radians(22.5));
prism {
    linear_sweep linear_spline -1.8, 1.8, 9,
    <Apothem, Half_Face>, <Half_Face, Apothem>, <-Half_Face, Apothem>, <-Apothem, Half_Face>,
    <-Apothem, -Half_Face>, <-Half_Face, -Apothem>, <Half_Face, -Apothem>, <Apothem, -Half_Face>,
    <Apothem, Half_Face>
    rotate -x * 90     // the prism's sweep (y) becomes z; its (x, z) outline becomes (x, y)
    pigment { rgb <0.35, 0.4, 0.55> }
    finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 30 }
}

// Sphere I bounces on face I: Bounces times over the animation, up to Lift
// above the face. Its phase puts each contact at an odd multiple of 1/32 of
// the clock: the middle of one of the 16 frames.
    #declare Radius = 0.33;
    #declare Lift = 1.0;
#for (I, 0, 7)
    #local Bounces = 1 + mod(I, 2);
    #local Phase = Bounces * (2 * I + 1) / 32;
    #local Angle = 45 * I;
    sphere {
        0, Radius
        translate x * (Apothem + Radius + Lift * abs(sin(pi * (Bounces * clock + Phase))))
        rotate z * Angle
        translate z * (-1.4 + 0.4 * I)
        pigment { rgb <0.55 + 0.45 * cos(radians(Angle)), 0.55 + 0.45 * cos(radians(Angle - 120)),
                       0.55 + 0.45 * cos(radians(Angle + 120))> }
        finish { ambient 0.1 diffuse 0.7 phong 0.8 phong_size 60 }
    }
#end
    rotate y * 55
    rotate x * 12
}

