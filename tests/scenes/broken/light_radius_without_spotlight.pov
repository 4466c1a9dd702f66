// error: 2:42: needs a spotlight or cylinder light
light_source { <0, 5, 0>, rgb 1 parallel radius 10 }
