// A blob's components with transforms and textures of their own, against
// POV-Ray 3.7 (tests/tracer/pov_reference_test.cpp, clock 0 and 0.5):
// stretched and turned spheres (POV-Ray's ellipsoid pieces), a cylinder
// scaled across its axis and turned with clock, a matrix, and component
// textures blended by density, a texture given before a transform moving
// with it, and a negative component with a pigment of its own (as
// advanced/abyss.pov's).
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
  sphere { 0, 1, 1 scale <1.4, 0.6, 0.8> rotate z * (30 + 60 * clock) translate <-0.4, 0, 0> }
  sphere { 0, 1, 1 pigment { color rgb <0.2, 0.4, 1> } scale <0.5, 1.3, 0.6> translate <0.6, 0.3, 0> }
  cylinder { -z, z, 0.4, -1 translate <-0.5, 0.2, -0.6> pigment { color rgb 0 } }
  pigment { color rgb <1, 0.4, 0.3> } finish { F }
  translate <-1.6, 1, 1.2>
}
blob {
  threshold 0.5
  cylinder { <-0.8, 0, 0>, <0.8, 0, 0>, 0.5, 1 scale <1, 1.6, 0.7> rotate y * 90 * clock }
  sphere { 0, 0.8, 1.5
    texture { pigment { checker color rgb <1, 1, 0.2>, color rgb <0.2, 0.8, 0.3> scale 0.2 } finish { F } }
    scale <1, 0.5, 1> translate <0, 0.4, 0> }
  sphere { 0, 0.6, 1 matrix <1, 0.4, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0> translate <0.7, 0.7, -0.3>
    pigment { color rgb <0.9, 0.3, 0.9> } }
  pigment { color rgb <0.3, 0.9, 0.4> } finish { F }
  rotate y * 20
  translate <1.6, 0.7, 1.2>
}
