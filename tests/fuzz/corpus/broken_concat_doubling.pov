// error: 6:16: concat()'s result would be 16777216 characters long
// A string doubled until it passes the default limit of 16 Mi characters.
#declare S = "a";
#declare N = 0;
#while (N < 100)
  #declare S = concat(S, S);
  #declare N = N + 1;
#end

