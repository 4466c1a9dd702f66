// Refraction decided by the interiors a ray has passed, as POV-Ray 3.7's
// ComputeRefraction and ComputeRelativeIOR decide it (trace.cpp), not by
// the side of the surface met: two overlapping glass spheres in a union
// (one interior: the overlap is left where the second is met), moving
// with clock; water in a glass (nested iors); a glass block with a hole
// carved by a member without an interior of its own; a height field
// turned upside down, whose open sides let rays into its solid, so that
// they enter where they meet its back faces. Fresnel reflection reads the
// same lists.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 12 }
camera { location <0.3, 2.2, -6> look_at <0, 0.6, 0> angle 50 }
light_source { <4, 8, -5> rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.3, 0.1, 0.2>] [1 rgb <0.9, 0.9, 1>] } } }
plane { y, -1 pigment { checker rgb <1, 0.4, 0.2> rgb <0.2, 0.4, 1> scale 0.5 } }
plane { -z, -5 pigment { checker rgb 1 rgb 0.1 scale 0.5 } }
#declare Glass = finish { specular 0.8 roughness 0.01 ambient 0 diffuse 0.05
                          reflection { 0, 1 fresnel } }
union {
  sphere { <-0.45, 0, 0>, 0.7 }
  sphere { <0.45, 0, 0>, 0.7 }
  pigment { rgbf <0.95, 1, 0.95, 0.95> } finish { Glass } interior { ior 1.5 }
  translate <-1.4 + 0.4 * clock, 1.5, 0>
}
// water in a glass
union {
  difference {
    cylinder { <0, 0, 0>, <0, 1.4, 0>, 0.6 }
    cylinder { <0, 0.15, 0>, <0, 1.5, 0>, 0.5 }
    pigment { rgbf <0.9, 0.95, 1, 0.9> } finish { Glass } interior { ior 1.5 }
  }
  cylinder { <0, 0.17, 0>, <0, 0.9 + 0.3 * clock, 0>, 0.47
    pigment { rgbf <0.8, 0.9, 1, 0.95> } finish { Glass } interior { ior 1.33 } }
  translate <1.5, -0.98, 0.5>
}
// a block with a carved hole, whose carving has no interior of its own
difference {
  box { <-0.5, -0.98, -0.5>, <0.5, 0.2, 0.5>
    pigment { rgbf <1, 1, 0.9, 0.9> } finish { Glass } interior { ior 1.45 } }
  sphere { <0, -0.4, 0>, 0.35 pigment { rgbt <0.9, 0.8, 0.5, 0.6> } finish { reflection 0.3 } }
  rotate 30 * clock * y
  translate <0, 0, -0.6>
}
// upside down: its solid lies above the surface, open at the sides
height_field {
  function 32, 32 { pigment { checker rgb 1 rgb 0 scale 1/4 } }
  translate <-0.5, 0, -0.5>
  scale <3, -0.3, 2>
  translate <-1.2, -0.55, 2.2>
  pigment { rgbf <0.98, 1, 0.98, 1> } finish { Glass } interior { ior 1.2 }
}
