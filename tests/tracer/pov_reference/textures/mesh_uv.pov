// A mesh of a triangle and a smooth_triangle with uv_vectors (POV-Ray's
// Parse_Three_UVCoords) under a uv-mapped checker, against POV-Ray 3.7
// (tests/tracer/pov_reference_test.cpp).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.5, 0.5, -2> look_at <0.5, 0.5, 0> angle 50 }
light_source { <-5, 8, -6> color rgb 1 }
mesh { triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> uv_vectors <0.1, 0.2>, <0.9, 0.2>, <0.1, 0.6> }
       smooth_triangle { <1, 0, 0>, <0,0,-1>, <1, 1, 0>, <0,0,-1>, <0, 1, 0>, <0,0,-1> uv_vectors <0.9, 0.2>, <0.5, 1>, <0.1, 0.6> }
       pigment { uv_mapping checker rgb <1,0.2,0.1>, rgb 0.9 scale 0.1 } finish { ambient 0.3 } }
