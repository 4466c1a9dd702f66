// error: 2:33: found 'twist'
light_source { <0, 5, 0>, rgb 1 twist y, 30 }

