// POV-Ray's commas between area_light's values and blur_samples' are
// optional (its Parse_Comma): both forms read.
camera { location <0, 0, -5> look_at 0 aperture 0.5 blur_samples 4 20 focal_point 0 }
light_source { <0, 5, 0>, rgb 1 area_light <4, 0, 0> <0, 0, 4> 3 3 orient }
light_source { <0, 5, 0>, rgb 1 area_light <4, 0, 0>, <0, 0, 4>, 3, 3 jitter circular }
sphere { 0, 1 }
