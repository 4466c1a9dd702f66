// error: 2:11: says it has 5 points but lists 4
polygon { 5, <0, 0>, <1, 0>, <1, 1>, <0, 1> }

