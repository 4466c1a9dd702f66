// radiosity.pov: a room lit by one light and by its own walls (radiosity,
// global_settings { radiosity { } }), with a glowing panel (emission), a
// ball that moves with clock, a mirror ball, an object hidden from
// radiosity's rays (no_radiosity) and, for a 3.7 scene, ambient that lights
// nothing. hexant against POV-Ray 3.7 (tests/tracer/pov_reference_radiosity_test.cpp).
#version 3.7;
global_settings {
  assumed_gamma 1.0
  radiosity {
    pretrace_start 0.08
    pretrace_end 0.02
    count 120
    nearest_count 8
    error_bound 0.6
    recursion_limit 2
    brightness 1.0
  }
}
camera { location <0, 2.2, -6.5> look_at <0, 1.6, 0> angle 60 }
light_source { <1.2, 3.6, -1.0> color rgb <1, 0.95, 0.85> * 0.7 }
#declare Wall = finish { diffuse 0.7 ambient 0.4 }
// floor, ceiling, back, left (red), right (green)
plane { y, 0 pigment { checker rgb 0.85 rgb 0.45 scale 0.75 } finish { Wall } }
plane { -y, -4 pigment { rgb 0.9 } finish { Wall } }
plane { -z, -3 pigment { rgb 0.8 } finish { Wall } }
plane { x, -3 pigment { rgb <0.75, 0.12, 0.1> } finish { Wall } }
plane { -x, -3 pigment { rgb <0.12, 0.6, 0.15> } finish { Wall } }
// behind the camera: a dark wall, so that rays out of the room meet something
plane { z, -8 pigment { rgb 0.3 } finish { Wall } }
// a glowing panel on the left wall (3.7's emission lights by radiosity)
box { <-2.99, 0.8, 0.5>, <-2.9, 2.4, 2.0> pigment { rgb <1, 0.8, 0.4> } finish { emission 1.5 diffuse 0 } }
// a ball rolling across the floor with clock
sphere { <-1.2 + 2.0 * clock, 0.7, 0.4>, 0.7 pigment { rgb <0.3, 0.45, 0.9> } finish { Wall } }
// a mirror ball
sphere { <1.6, 0.5, 1.6>, 0.5 pigment { rgb 0.2 } finish { diffuse 0.2 reflection 0.7 } }
// a pillar radiosity's rays do not see: it casts no indirect shade
box { <0.6, 0, 2.0>, <1.1, 3.0, 2.5> pigment { rgb 0.95 } finish { Wall } no_radiosity }
