// error: 2:33: area_light's second size 0 is out of range
light_source { <0, 5, 0>, rgb 1 area_light x, z, 4, 0.5 }
