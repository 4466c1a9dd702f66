// error: 2:14: 2 to 5 components, not 6
#declare V = <1, 2, 3, 4, 5, 6>;

