// density_file df3: an 8-bit voxel file as emitting media's density in
// three boxes, without interpolation, trilinear and tricubic (the
// distribution's galaxy.pov's kind), turning with clock.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -6> look_at <0, 0.5, 0> }
light_source { <4, 6, -5>, rgb 1 }
plane { y, -0.6 pigment { checker rgb 0.7, rgb 0.4 } }
#macro Voxels(N, X)
box { 0, 1
  pigment { rgbt 1 }
  interior { media {
    emission 3 samples 6
    density { density_file df3 "blob.df3" interpolate N
      color_map { [0 rgb 0] [0.3 rgb <0.2, 0.3, 1>] [1 rgb <1, 0.9, 0.5>] } }
  } }
  hollow
  translate -0.5 scale 1.4 rotate y * (20 + 40 * clock) translate <X, 0.3, 0>
}
#end
Voxels(0, -1.7)
Voxels(1, 0)
Voxels(2, 1.7)
