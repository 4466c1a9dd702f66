// error: 2:1: a circular area_light needs more than 1 light along each axis
light_source { <0, 5, 0>, rgb 1 area_light x, z, 4, 1 circular }
