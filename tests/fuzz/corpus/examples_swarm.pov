// swarm.pov: the scale scene. N small spheres on random tilted circular
// orbits, each turning 1 to 4 times over the animation, above a checked
// floor. N defaults to 1000; `--declare N=100000` (or POV-Ray's
// Declare=N=100000) sets it. Cyclic: every orbit turns a whole number of
// times over the clock range 0..1.
//
// Render with hexant:   build/hexant render examples/swarm.pov examples/swarm.ini
// Benchmark the build:  sh tests/bench/scale.sh
// Render with POV-Ray:  povray examples/swarm.ini examples/swarm.pov
#version 3.7;

global_settings { assumed_gamma 1.0 }

#ifndef (N) #declare N = 1000; #end

camera {
    location <0, 14, -26>
    look_at <0, 1, 0>
    angle 45
    right x * image_width / image_height
}

light_source { <-20, 40, -30>, rgb 1 }
background { rgb <0.02, 0.02, 0.05> }

plane {
    y, -6
    pigment { checker rgb <0.75, 0.75, 0.7>, rgb <0.45, 0.45, 0.5> scale 2 }
    finish { ambient 0.15 diffuse 0.8 }
}

// The spheres fill a ball of radius 10 more or less evenly: the sphere's
// size falls with N so that the swarm covers a similar share of the image.
#declare Size = 0.3 / pow(N / 1000, 1 / 3);
#declare S = seed(1988);
#declare I = 0;
#while (I < N)
    #declare Orbit = 1 + 9 * pow(rand(S), 1 / 3);
    #declare Turns = 1 + floor(4 * rand(S));
    #declare Tilt = <180 * rand(S) - 90, 0, 180 * rand(S) - 90>;
    sphere {
        <Orbit, 0, 0>, Size
        rotate y * (360 * rand(S) + 360 * Turns * clock)
        rotate Tilt
        pigment { rgb <0.3 + 0.7 * rand(S), 0.3 + 0.7 * rand(S), 0.3 + 0.7 * rand(S)> }
        finish { phong 0.6 phong_size 40 }
    }
    #declare I = I + 1;
#end

