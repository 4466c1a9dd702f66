// blob against POV-Ray 3.7 (tests/tracer/pov_reference_test.cpp, clock 0
// and 0.5): two spheres that move together and merge with clock, a
// cylinder with a sphere on it, a negative component cutting a dent, the
// old component syntax, a threshold that moves, over a checkered floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.8, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
light_source { <5, 3, -3> color rgb 0.3 }
background { color rgb <0.15, 0.2, 0.35> }
plane { y, 0 pigment { checker color rgb 0.9, color rgb 0.35 scale 0.5 } }
#declare F = finish { phong 0.5 phong_size 30 }
blob {
  threshold 0.6
  sphere { <-0.9 + 0.6 * clock, 0, 0>, 1, 1 }
  sphere { <0.9 - 0.6 * clock, 0, 0>, 1, strength 1 }
  pigment { color rgb <1, 0.4, 0.3> } finish { F }
  translate <-1.8, 1, 1.5>
}
blob {
  threshold 0.5
  cylinder { <-0.8, 0, 0>, <0.8, 0, 0>, 0.5, 1 }
  sphere { <0, 0.4, 0>, 0.8, 1.5 }
  sphere { <0.2, 0.9, -0.4>, 0.5, -2 }
  pigment { color rgb <0.3, 0.9, 0.4> } finish { F }
  rotate y * (20 + 30 * clock)
  translate <1.8, 0.7, 1.5>
}
blob {
  threshold 0.3 + 0.3 * clock
  component 1, 0.8, <-0.4, 0, 0>
  component 1, 0.8, <0.4, 0, 0>
  component 1, 0.8, <0, 0.5, 0>
  pigment { color rgb <0.3, 0.5, 1> } finish { F }
  translate <0, 0.6, -1.2>
}
