// photons.pov: caustics by photon mapping (global_settings { photons { } }):
// a glass ball that refracts a point light's photons into a bright spot on
// the floor and moves with clock, a mirror that reflects a spotlight's
// photons onto the wall, an object whose photons are not collected, and a
// light whose photons are turned off for refraction. hexant against
// POV-Ray 3.7 (tests/tracer/pov_reference_photons_test.cpp).
#version 3.7;
global_settings {
  assumed_gamma 1.0
  max_trace_level 10
  // (--declare Photons=0: the same scene without photon mapping, for the
  // test's measure of what photons add.)
  #ifndef (Photons) #declare Photons = 1; #end
  #if (Photons) photons { spacing 0.01 autostop 0 jitter 0.4 } #end
}
camera { location <0, 5.5, -4> look_at <0, 0, 0.6> angle 55 }
light_source { <-2.5, 5, 2.5> color rgb 0.9 }
light_source {
  <3, 2.5, -2.5> color rgb <1, 0.9, 0.7>
  spotlight point_at <1.2, 0.6, 1.5> radius 12 falloff 20
  photons { refraction off reflection on }
}
plane { y, 0 pigment { checker rgb 0.7 rgb 0.5 scale 0.8 } finish { diffuse 0.8 ambient 0 } }
plane { -z, -3 pigment { rgb 0.75 } finish { diffuse 0.8 ambient 0 } }
// the glass ball, rolling along x with clock
sphere {
  <-0.8 + 0.6 * clock, 0.7, 0.2>, 0.7
  pigment { rgbf <0.95, 0.97, 1, 0.95> }
  finish { ambient 0 diffuse 0 specular 0.6 roughness 0.005 reflection 0.05 }
  interior { ior 1.5 }
  photons { target refraction on reflection on }
}
// a round mirror: it reflects the spotlight's photons onto the floor
disc {
  <1.2, 0.6, 1.5>, <-0.816, 0.091, -0.573>, 0.5
  pigment { rgb 0.1 } finish { ambient 0 diffuse 0.1 reflection 0.9 }
  photons { target reflection on }
}
// a block that takes no photons (collect off): no caustic on it
box { <1.4, 0, -1.2>, <2.2, 0.5, -0.4> pigment { rgb <0.9, 0.6, 0.4> } finish { diffuse 0.8 ambient 0 } photons { collect off } }
