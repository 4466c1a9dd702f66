// error: 2:2: unknown directive '#frobnicate'
#frobnicate 3

